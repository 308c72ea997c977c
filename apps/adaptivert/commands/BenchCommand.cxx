// adaptivert bench <what>: runs a registered benchmark (Bench.h).
#include "benchmarks/Bench.h"
#include "cli/Command.h"
#include "Error.h"

#include <filesystem>

namespace cli
{
std::vector<BenchTarget>& BenchTargets()
{
  static std::vector<BenchTarget> t;
  return t;
}
}

namespace
{
void Declare(cli::Options& o)
{
  o.Add("results", 0, "DIR", "folder for the JSON, markdown table and PNG chart", "bench-results");
  o.Add("runs", 0, "N", "timed runs per figure (the median is reported, min-max shown)", "5");
  for (const auto& t : cli::BenchTargets())
  {
    if (t.declare)
    {
      t.declare(o);
    }
  }
}

int Run(const cli::Options& o)
{
  std::string names;
  for (const auto& t : cli::BenchTargets())
  {
    names += (names.empty() ? "" : ", ") + t.name;
  }
  if (o.Positional().empty())
  {
    throw cli::UsageError("needs a benchmark name: " + (names.empty() ? std::string("none built") : names));
  }
  // --runs 0 or -1 ran a full benchmark as if it were 1 (the median of one run, no spread).
  const long long runs = o.GetInt("runs");
  if (runs < 1 || runs > 1000)
  {
    throw cli::UsageError("--runs expects 1..1000 timed runs, got '" + o.Get("runs") + "'");
  }
  for (const auto& t : cli::BenchTargets())
  {
    if (t.name == o.Positional()[0])
    {
      // One line naming the folder (a file in the way said "filesystem error: cannot create
      // directories: Not a directory [...]").
      std::error_code ec;
      const std::string dir = o.Get("results");
      std::filesystem::create_directories(dir, ec);
      if (!std::filesystem::is_directory(dir))
      {
        throw art::Error("cannot make the results folder" + (ec ? ": " + ec.message() : std::string()), dir);
      }
      return t.run(o);
    }
  }
  throw cli::UsageError("unknown benchmark '" + o.Positional()[0] + "' (have: " + names + ")");
}

cli::Registrar reg({ "bench", "run a benchmark: tables, JSON and a PNG chart, against VTK and Embree",
  "adaptivert bench [options] tets|reduction|triangles",
  "  adaptivert bench triangles --results out/\n  adaptivert bench reduction --runs 3\n",
  Declare, Run });
} // namespace
