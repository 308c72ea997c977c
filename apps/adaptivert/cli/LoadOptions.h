// LoadOptions: the options of the commands that load volumes (render, reduce, info; batch
// settings through render): --frame patient|vtk and a raw volume's layout, --raw-dims
// --raw-type --raw-spacing --raw-header --raw-endian --raw-components, as ParaView's raw
// reader takes it.
#ifndef adaptivert_LoadOptions_h
#define adaptivert_LoadOptions_h

#include "DataLoader.h"
#include "cli/Options.h"

#include <string>

namespace cli
{
/// Declares --frame and the --raw-* options.
void AddLoadOptions(Options& o);
/// The options as art::LoadOptions (with --array when declared); UsageError for a bad value.
art::LoadOptions LoadOptionsFrom(const Options& o);
/// Whether `option` is one of those AddLoadOptions declares.
bool IsLoadOption(const std::string& option);
} // namespace cli

#endif
