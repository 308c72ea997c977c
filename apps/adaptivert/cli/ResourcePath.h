// ResourcePath: where the tool's own files are (the default CT head, the chart script). An
// installed copy finds them under <prefix>/share/adaptivert beside its bin/, so it keeps working
// once the source tree is gone; a build tree uses the source tree's.
#ifndef adaptivert_ResourcePath_h
#define adaptivert_ResourcePath_h

#include <string>

namespace cli
{
/// <prefix>/share/adaptivert/<sub> when the running executable sits in <prefix>/bin and that
/// exists, else `source` (a path in the source tree, compiled in).
std::string ResourcePath(const std::string& sub, const std::string& source);
/// The default data folder (data/ of the source tree, or the installed copy of its small files).
std::string DataDir();
} // namespace cli

#endif
