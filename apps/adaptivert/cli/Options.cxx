#include "cli/Options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cli
{
namespace
{
std::size_t EditDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t up = row[j];
      row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1) });
      diag = up;
    }
  }
  return row[b.size()];
}
} // namespace

std::string Options::Suggest(const std::string& name) const
{
  // The declared option nearest in spelling, if it is near: a typo or a shortened name.
  std::string best;
  std::size_t bestDistance = name.size() < 4 ? 1 : 2;
  for (const auto& candidate : Order)
  {
    const std::size_t d = EditDistance(name, candidate);
    if (d <= bestDistance && (best.empty() || d < bestDistance))
    {
      best = candidate;
      bestDistance = d;
    }
  }
  return best;
}

void Options::Add(const std::string& name, char shortName, const std::string& value,
  const std::string& help, const std::string& def)
{
  Specs[name] = { shortName, value, help, def };
  Order.push_back(name);
}

void Options::Parse(int argc, char** argv, int first)
{
  bool onlyPositional = false;
  for (int i = first; i < argc; ++i)
  {
    std::string a = argv[i];
    if (onlyPositional || a.size() < 2 || a[0] != '-')
    {
      Args.push_back(a);
      continue;
    }
    if (a == "--")
    {
      onlyPositional = true;
      continue;
    }
    std::string name, value;
    bool inlineValue = false;
    if (a.rfind("--", 0) == 0)
    {
      name = a.substr(2);
      const auto eq = name.find('=');
      if (eq != std::string::npos)
      {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        inlineValue = true;
      }
    }
    else
    {
      for (const auto& [n, s] : Specs)
      {
        if (a.size() == 2 && s.shortName == a[1])
        {
          name = n;
        }
      }
      if (name.empty())
      {
        throw UsageError("unknown option '" + a + "'");
      }
    }
    const auto it = Specs.find(name);
    if (it == Specs.end())
    {
      const std::string near = Suggest(name);
      throw UsageError("unknown option '--" + name + "'" + (near.empty() ? "" : " (did you mean --" + near + "?)"));
    }
    if (it->second.value.empty())
    {
      if (inlineValue)
      {
        throw UsageError("option '--" + name + "' takes no value");
      }
      Values[name] = "1";
      continue;
    }
    if (!inlineValue)
    {
      if (i + 1 >= argc)
      {
        throw UsageError("option '--" + name + "' needs a value (" + it->second.value + ")");
      }
      value = argv[++i];
    }
    Values[name] = value;
  }
}

bool Options::Has(const std::string& name) const
{
  return Values.count(name) != 0;
}

std::string Options::Get(const std::string& name) const
{
  const auto v = Values.find(name);
  if (v != Values.end())
  {
    return v->second;
  }
  const auto s = Specs.find(name);
  return s == Specs.end() ? std::string() : s->second.def;
}

bool IsDecimalNumber(const std::string& v)
{
  // Digits, a point, an exponent, a sign: strtod also takes hexadecimal ("0x10" read as 16),
  // "inf", "nan" and leading blanks, which no option means.
  if (v.empty() || v.find_first_not_of("0123456789.eE+-") != std::string::npos)
  {
    return false;
  }
  char* end = nullptr;
  std::strtod(v.c_str(), &end);
  return end != v.c_str() && *end == '\0';
}

double Options::GetDouble(const std::string& name) const
{
  const std::string v = Get(name);
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  // strtod takes "nan", which no option means and which slips past range checks written as
  // comparisons (--azimuth nan crashed the voxel reference).
  // Hexadecimal ("0x10") is no number an option means either; infinities are left to the
  // options' range checks, which name them.
  if (v.empty() || *end != '\0' || std::isnan(d) || v.find_first_of("xX \t") != std::string::npos)
  {
    throw UsageError("option '--" + name + "' expects a number, got '" + v + "'");
  }
  return d;
}

long long GetIntImpl(const std::string& name, const std::string& v)
{
  char* end = nullptr;
  const long long n = std::strtoll(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || v.find_first_not_of("0123456789+-") != std::string::npos)
  {
    throw UsageError("option '--" + name + "' expects an integer, got '" + v + "'");
  }
  return n;
}

long long Options::GetInt(const std::string& name) const
{
  return GetIntImpl(name, Get(name));
}

void Options::GetSize(const std::string& name, int& w, int& h) const
{
  const std::string v = Get(name);
  const auto x = v.find_first_of("xX");
  if (x == std::string::npos)
  {
    throw UsageError("option '--" + name + "' expects WxH, got '" + v + "'");
  }
  const long long a = GetIntImpl(name, v.substr(0, x)), b = GetIntImpl(name, v.substr(x + 1));
  if (a < 1 || b < 1 || a > 16384 || b > 16384)
  {
    throw UsageError("option '--" + name + "' size out of range 1..16384: '" + v + "'");
  }
  w = static_cast<int>(a);
  h = static_cast<int>(b);
}

std::string Options::Help() const
{
  std::ostringstream os;
  for (const auto& name : Order)
  {
    const Spec& s = Specs.at(name);
    std::string left = "  ";
    left += s.shortName ? std::string("-") + s.shortName + ", " : std::string("    ");
    left += "--" + name + (s.value.empty() ? "" : " " + s.value);
    os << left;
    os << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << s.help;
    if (!s.def.empty())
    {
      os << " (default " << s.def << ")";
    }
    os << "\n";
  }
  return os.str();
}
} // namespace cli
