// adaptivert: the command-line tool. `adaptivert <subcommand> [options] INPUT...`
// Errors: one line "adaptivert: <file>: <what>" on stderr; exit 1 at run time, 2 for usage.
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace
{
void PrintOverview()
{
  std::printf("adaptivert %s - adaptive tetrahedral reduction and ray casting around VTK\n\n"
              "usage: adaptivert <command> [options] INPUT...\n\ncommands:\n",
    ART_VERSION);
  for (const auto& c : cli::Registry())
  {
    std::printf("  %-10s %s\n", c.name.c_str(), c.summary.c_str());
  }
  const art::InputFormatList f = art::InputFormats();
  std::printf("\ninputs (by extension):\n  volumes    %s\n  surfaces   %s\n  meshes     %s\n  and        %s\n",
    f.volumes.c_str(), f.surfaces.c_str(), f.meshes.c_str(), f.any.c_str());
  std::printf("\n'adaptivert <command> --help' shows a command's options and examples.\n"
              "Exit codes: 0 success, 1 run-time failure (bad file, failed check), 2 usage error.\n");
}

} // namespace

int main(int argc, char** argv)
{
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
    !std::strcmp(argv[1], "help"))
  {
    PrintOverview();
    return argc < 2 ? cli::ExitUsage : cli::ExitOk;
  }
  if (!std::strcmp(argv[1], "--version"))
  {
    std::printf("adaptivert %s\n", ART_VERSION);
    return cli::ExitOk;
  }
  const cli::Command* cmd = cli::FindCommand(argv[1]);
  if (!cmd)
  {
    std::fprintf(stderr, "adaptivert: unknown command '%s' (try 'adaptivert --help')\n", argv[1]);
    return cli::ExitUsage;
  }
  try
  {
    return cli::RunCommand(*cmd, std::vector<std::string>(argv + 2, argv + argc));
  }
  catch (const cli::UsageError& e)
  {
    std::fprintf(stderr, "adaptivert %s: %s (try 'adaptivert %s --help')\n", cmd->name.c_str(),
      e.what(), cmd->name.c_str());
    return cli::ExitUsage;
  }
  catch (const art::Error& e)
  {
    std::fprintf(stderr, "adaptivert: %s\n", e.what());
    return cli::ExitFailure;
  }
  catch (const std::bad_alloc&)
  {
    std::fprintf(stderr, "adaptivert: out of memory\n");
    return cli::ExitFailure;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "adaptivert: %s\n", e.what());
    return cli::ExitFailure;
  }
}
