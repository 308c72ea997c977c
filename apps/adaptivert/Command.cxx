#include "Command.h"

#include <algorithm>

namespace cli
{
std::vector<Command>& Registry()
{
  static std::vector<Command> commands;
  return commands;
}

const Command* FindCommand(const std::string& name)
{
  const auto& r = Registry();
  auto it = std::find_if(r.begin(), r.end(), [&](const Command& c) { return c.name == name; });
  return it == r.end() ? nullptr : &*it;
}
} // namespace cli
