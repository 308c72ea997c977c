// Error: the one exception type engines throw for bad input. It names the file (when there is
// one) and what is wrong, so the CLI can print "adaptivert: <file>: <what>" and exit 1. The text
// is kept to one printable line: bytes quoted from a damaged file (control characters, stray
// binary) are escaped as \xNN, so an error never garbles a terminal or spans lines.
#ifndef art_Error_h
#define art_Error_h

#include <cstdio>
#include <stdexcept>
#include <string>

namespace art
{
/// `text` as one printable line: tabs, line ends and other control bytes, and bytes that are not
/// part of valid UTF-8, become "\xNN"; valid UTF-8 (accented file names) is kept.
inline std::string Printable(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  auto escape = [&out](unsigned char c) {
    char hex[5];
    std::snprintf(hex, sizeof hex, "\\x%02X", c);
    out += hex;
  };
  for (std::size_t i = 0; i < n;)
  {
    const unsigned char c = s[i];
    if (c >= 0x20 && c < 0x7F)
    {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    // The length of a well-formed UTF-8 sequence starting here, or 0.
    std::size_t len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    for (std::size_t k = 1; len && k < len; ++k)
    {
      len = i + k < n && (s[i + k] & 0xC0) == 0x80 ? len : 0;
    }
    if (len)
    {
      out.append(text, i, len);
      i += len;
    }
    else
    {
      escape(c);
      ++i;
    }
  }
  return out;
}

class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& what, std::string file = {})
    : std::runtime_error(Printable(file.empty() ? what : file + ": " + what))
    , File(std::move(file))
    , What(Printable(what))
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
