#include "cli/Json.h"

#include <cmath>
#include <cstdio>

namespace cli
{
std::string Json::Quote(const std::string& s)
{
  std::string o = "\"";
  for (unsigned char c : s)
  {
    switch (c)
    {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (c < 0x20)
        {
          char b[8];
          std::snprintf(b, sizeof b, "\\u%04x", c);
          o += b;
        }
        else
        {
          o += static_cast<char>(c);
        }
    }
  }
  return o + "\"";
}

namespace
{
std::string Number(double v)
{
  if (!std::isfinite(v))
  {
    return "null"; // JSON has no infinity (PSNR of identical images)
  }
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}
}

Json& Json::Set(const std::string& k, const std::string& v) { Items.emplace_back(k, Quote(v)); return *this; }
Json& Json::Set(const std::string& k, double v) { Items.emplace_back(k, Number(v)); return *this; }
Json& Json::Set(const std::string& k, long long v) { Items.emplace_back(k, std::to_string(v)); return *this; }
Json& Json::Set(const std::string& k, bool v) { Items.emplace_back(k, v ? "true" : "false"); return *this; }
Json& Json::Set(const std::string& k, const Json& o) { Items.emplace_back(k, o.Str()); return *this; }

Json& Json::Set(const std::string& k, const std::vector<double>& v)
{
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i)
  {
    s += (i ? "," : "") + Number(v[i]);
  }
  Items.emplace_back(k, s + "]");
  return *this;
}

Json& Json::Set(const std::string& k, const std::vector<std::string>& v)
{
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i)
  {
    s += (i ? "," : "") + Quote(v[i]);
  }
  Items.emplace_back(k, s + "]");
  return *this;
}

Json& Json::Set(const std::string& k, const std::vector<Json>& a)
{
  std::string s = "[";
  for (size_t i = 0; i < a.size(); ++i)
  {
    s += (i ? "," : "") + a[i].Str();
  }
  Items.emplace_back(k, s + "]");
  return *this;
}

std::string Json::Str() const
{
  std::string s = "{";
  for (size_t i = 0; i < Items.size(); ++i)
  {
    s += (i ? "," : "") + Quote(Items[i].first) + ":" + Items[i].second;
  }
  return s + "}";
}
} // namespace cli
