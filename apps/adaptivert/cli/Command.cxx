#include "cli/Command.h"
#include "ParallelTiles.h"

#include <vtkLogger.h>
#include <vtkOutputWindow.h>

#include <algorithm>
#include <cstdio>

namespace cli
{
std::vector<Command>& Registry()
{
  static std::vector<Command> commands;
  return commands;
}

const Command* FindCommand(const std::string& name)
{
  const auto& r = Registry();
  auto it = std::find_if(r.begin(), r.end(), [&](const Command& c) { return c.name == name; });
  return it == r.end() ? nullptr : &*it;
}
void AddCommonOptions(Options& o)
{
  o.Add("help", 'h', "", "show this help and exit");
  o.Add("threads", 0, "N", "worker threads, 0 = all cores", "0");
  o.Add("json", 0, "", "print one JSON object on stdout instead of text");
  o.Add("quiet", 'q', "", "no progress on stderr (a job running past a minute still says so once a minute)");
  o.Add("verbose", 'v', "", "show VTK's own warnings and errors too");
}

int RunCommand(const Command& cmd, const std::vector<std::string>& args)
{
  Options opts;
  if (cmd.declare)
  {
    cmd.declare(opts);
  }
  AddCommonOptions(opts);
  std::vector<char*> argv;
  for (const auto& a : args)
  {
    argv.push_back(const_cast<char*>(a.c_str()));
  }
  opts.Parse(static_cast<int>(argv.size()), argv.data(), 0);
  if (opts.Flag("help"))
  {
    std::printf("usage: %s\n\n%s\n\noptions:\n%s", cmd.usage.c_str(), cmd.summary.c_str(), opts.Help().c_str());
    if (!cmd.examples.empty())
    {
      std::printf("\nexamples:\n%s", cmd.examples.c_str());
    }
    return ExitOk;
  }
  // VTK's readers report through its output window; we report errors ourselves, in one line.
  if (!opts.Flag("verbose"))
  {
    vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  const long long threads = opts.GetInt("threads");
  if (threads < 0 || threads > 4096)
  {
    throw UsageError("--threads expects 0 (all cores) or a count up to 4096, got '" + opts.Get("threads") + "'");
  }
  art::SetThreadCount(static_cast<int>(threads));
  return cmd.run(opts);
}
} // namespace cli
