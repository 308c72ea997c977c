// NumberFormat: counts as the CLI prints them, in groups of three digits ("12,345").
#ifndef adaptivert_NumberFormat_h
#define adaptivert_NumberFormat_h

#include <string>

namespace cli
{
/// 12345 -> "12,345"; -1234 -> "-1,234".
std::string Grouped(long long n);
} // namespace cli

#endif
