// Error: the one exception type engines throw for bad input. It names the file (when there is
// one) and what is wrong, so the CLI can print "adaptivert: <file>: <what>" and exit 1.
#ifndef art_Error_h
#define art_Error_h

#include <stdexcept>
#include <string>

namespace art
{
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& what, std::string file = {})
    : std::runtime_error(file.empty() ? what : file + ": " + what)
    , File(std::move(file))
    , What(what)
  {
  }
  const std::string& file() const { return File; }
  const std::string& problem() const { return What; }

private:
  std::string File;
  std::string What;
};
} // namespace art

#endif
