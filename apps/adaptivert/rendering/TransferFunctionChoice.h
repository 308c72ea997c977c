// TransferFunctionChoice: what --tf names, checked before any data is read: a preset, or a file
// that exists. Anything else is a usage error that says both were looked for.
#ifndef adaptivert_TransferFunctionChoice_h
#define adaptivert_TransferFunctionChoice_h

#include <string>

namespace cli
{
/// Throws UsageError unless `tf` is a transfer-function preset or names an existing file (a
/// missing file named like one, with a '.' or '/', is left for the reader to report).
void CheckTransferFunctionName(const std::string& tf);
} // namespace cli

#endif
