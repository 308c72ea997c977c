// Command: a subcommand of the adaptivert CLI. Each commands/<Name>Command.cxx defines one
// and registers it with a static Registrar; main() looks commands up by name.
#ifndef adaptivert_Command_h
#define adaptivert_Command_h

#include "cli/Options.h"

#include <string>
#include <vector>

namespace cli
{
struct Command
{
  std::string name;
  std::string summary;  ///< one line for `adaptivert --help`
  std::string usage;    ///< "adaptivert info [options] FILE..."
  std::string examples; ///< shown by --help
  void (*declare)(Options&) = nullptr;
  int (*run)(const Options&) = nullptr; ///< returns the exit code; throws art::Error or UsageError
};

std::vector<Command>& Registry();
const Command* FindCommand(const std::string& name);

/// The options every command takes: --help --threads --json --quiet --verbose.
void AddCommonOptions(Options& o);
/// Declares `cmd`'s options, parses `args` (after the command name), applies --threads and
/// --verbose, and runs it. Used by main() and by commands that run another command (demo).
int RunCommand(const Command& cmd, const std::vector<std::string>& args);

struct Registrar
{
  explicit Registrar(Command c) { Registry().push_back(std::move(c)); }
};

/// Exit codes, documented in docs/cli.md.
enum ExitCode
{
  ExitOk = 0,
  ExitFailure = 1, ///< run-time failure: bad file, I/O error, image over threshold
  ExitUsage = 2    ///< bad command line
};
} // namespace cli

#endif
