// Options: GNU-style long options (--name value, --name=value), a few short ones (-o), flags,
// and positional arguments. Unknown options and missing values are usage errors (exit 2).
#ifndef adaptivert_Options_h
#define adaptivert_Options_h

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace cli
{
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// A plain decimal number ("12", "0.5", "1e-3"); not hexadecimal, "inf", "nan" or blanks.
bool IsDecimalNumber(const std::string& v);

class Options
{
public:
  /// Declares --name (and -s when shortName != 0). `value` names the argument ("N", "FILE");
  /// empty means a flag. `def` is the default shown in help and returned by Get.
  void Add(const std::string& name, char shortName, const std::string& value,
    const std::string& help, const std::string& def = "");

  /// Parses argv[first..argc); throws UsageError.
  void Parse(int argc, char** argv, int first);

  bool Has(const std::string& name) const; ///< given on the command line
  bool Flag(const std::string& name) const { return Has(name); }
  std::string Get(const std::string& name) const; ///< value or default
  double GetDouble(const std::string& name) const;
  long long GetInt(const std::string& name) const;
  /// "WxH" into two positive ints.
  void GetSize(const std::string& name, int& w, int& h) const;
  const std::vector<std::string>& Positional() const { return Args; }
  /// Names declared with Add, in order.
  const std::vector<std::string>& Declared() const { return Order; }

  std::string Help() const;

  /// The declared option whose name is within a typo of `name` ("tet" -> "tets"), or "".
  std::string Suggest(const std::string& name) const;

private:
  struct Spec
  {
    char shortName;
    std::string value, help, def;
  };
  std::map<std::string, Spec> Specs;
  std::vector<std::string> Order;
  std::map<std::string, std::string> Values;
  std::vector<std::string> Args;
};
} // namespace cli

#endif
