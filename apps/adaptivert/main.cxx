// adaptivert: the command-line tool. `adaptivert <subcommand> [options] INPUT...`
// Errors: one line "adaptivert: <file>: <what>" on stderr; exit 1 at run time, 2 for usage.
#include "Command.h"
#include "Error.h"
#include "ParallelTiles.h"

#include <vtkLogger.h>
#include <vtkOutputWindow.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

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
  std::printf("\n'adaptivert <command> --help' shows a command's options and examples.\n"
              "Exit codes: 0 success, 1 run-time failure (bad file, failed check), 2 usage error.\n");
}

void AddCommonOptions(cli::Options& o)
{
  o.Add("help", 'h', "", "show this help and exit");
  o.Add("threads", 0, "N", "worker threads, 0 = all cores", "0");
  o.Add("json", 0, "", "print one JSON object on stdout instead of text");
  o.Add("quiet", 'q', "", "no progress on stderr");
  o.Add("verbose", 'v', "", "show VTK's own warnings and errors too");
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
  cli::Options opts;
  if (cmd->declare)
  {
    cmd->declare(opts);
  }
  AddCommonOptions(opts);
  try
  {
    opts.Parse(argc, argv, 2);
    if (opts.Flag("help"))
    {
      std::printf("usage: %s\n\n%s\n\noptions:\n%s", cmd->usage.c_str(), cmd->summary.c_str(),
        opts.Help().c_str());
      if (!cmd->examples.empty())
      {
        std::printf("\nexamples:\n%s", cmd->examples.c_str());
      }
      return cli::ExitOk;
    }
    // VTK's readers report through its output window; we report errors ourselves, in one line.
    if (!opts.Flag("verbose"))
    {
      vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    }
    art::SetThreadCount(static_cast<int>(opts.GetInt("threads")));
    return cmd->run(opts);
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
