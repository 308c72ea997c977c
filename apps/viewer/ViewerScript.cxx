#include "ViewerScript.h"

#include "Error.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace view
{
std::vector<ScriptAction> ReadScript(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    throw art::Error("is a directory, expected a script file", path); // it read as an empty script
  }
  std::ifstream in(path);
  if (!in)
  {
    throw art::Error("cannot open script", path);
  }
  std::vector<ScriptAction> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
  {
    if (n == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
    {
      line.erase(0, 3); // a UTF-8 byte-order mark (Windows editors): "unknown action 'key'" with it
    }
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::istringstream ss(line);
    std::string word;
    if (!(ss >> word))
    {
      continue;
    }
    auto fail = [&](const std::string& what) {
      throw art::Error("line " + std::to_string(n) + ": " + what, path);
    };
    ScriptAction a;
    a.Line = n;
    std::string rest;
    if (word == "key")
    {
      a.What = ScriptAction::Kind::Key;
      if (!(ss >> a.Text) || a.Text.size() != 1)
      {
        fail("'key' expects one character");
      }
    }
    else if (word == "wait-reduction")
    {
      a.What = ScriptAction::Kind::WaitReduction;
    }
    else if (word == "drag")
    {
      a.What = ScriptAction::Kind::Drag;
      if (!(ss >> a.Value >> a.Value2) || std::abs(a.Value) > 1e4 || std::abs(a.Value2) > 1e4)
      {
        fail("'drag' expects DX DY in pixels");
      }
    }
    else if (word == "screenshot")
    {
      // The rest of the line is the file's name, spaces and all ("screenshot my view.png" was
      // "unexpected 'view.png'"); blanks (and a CRLF's CR) around it are not part of it.
      a.What = ScriptAction::Kind::Screenshot;
      std::getline(ss, a.Text);
      const auto first = a.Text.find_first_not_of(" \t\r"), last = a.Text.find_last_not_of(" \t\r");
      a.Text = first == std::string::npos ? std::string() : a.Text.substr(first, last - first + 1);
      if (a.Text.empty())
      {
        fail("'screenshot' expects a file");
      }
    }
    else
    {
      static const std::pair<const char*, ScriptAction::Kind> numeric[] = { { "wait", ScriptAction::Kind::Wait },
        { "azimuth", ScriptAction::Kind::Azimuth }, { "elevation", ScriptAction::Kind::Elevation },
        { "roll", ScriptAction::Kind::Roll }, { "zoom", ScriptAction::Kind::Zoom } };
      bool known = false;
      for (const auto& k : numeric)
      {
        if (word == k.first)
        {
          a.What = k.second;
          known = true;
        }
      }
      if (!known)
      {
        fail("unknown action '" + word + "'");
      }
      if (!(ss >> a.Value) || !std::isfinite(a.Value))
      {
        fail("'" + word + "' expects a number");
      }
      if ((a.What == ScriptAction::Kind::Wait && a.Value < 0) || (a.What == ScriptAction::Kind::Zoom && a.Value <= 0))
      {
        fail("'" + word + "' expects a positive number");
      }
    }
    if (ss >> rest)
    {
      fail("unexpected '" + rest + "'");
    }
    out.push_back(a);
  }
  return out;
}
} // namespace view
