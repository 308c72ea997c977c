// Json: a tiny writer for the --json output of every subcommand (one object per run).
#ifndef adaptivert_Json_h
#define adaptivert_Json_h

#include <string>
#include <vector>

namespace cli
{
class Json
{
public:
  Json& Set(const std::string& key, const std::string& v);
  Json& Set(const std::string& key, const char* v) { return Set(key, std::string(v)); }
  Json& Set(const std::string& key, double v);
  Json& Set(const std::string& key, long long v);
  Json& Set(const std::string& key, int v) { return Set(key, static_cast<long long>(v)); }
  Json& Set(const std::string& key, bool v);
  Json& Set(const std::string& key, const std::vector<double>& v);
  Json& Set(const std::string& key, const std::vector<std::string>& v);
  Json& Set(const std::string& key, const Json& object);
  Json& Set(const std::string& key, const std::vector<Json>& array);
  std::string Str() const;
  static std::string Quote(const std::string& s);

private:
  std::vector<std::pair<std::string, std::string>> Items; // key, encoded value
};
} // namespace cli

#endif
