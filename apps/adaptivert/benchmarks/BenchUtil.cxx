#include "benchmarks/BenchUtil.h"
#include "Error.h"
#include "cli/Subprocess.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace cli
{
namespace
{
std::string Shell(const std::string& cmd)
{
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r"))
  {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p))
    {
      out += buf;
    }
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r' || out.back() == ' '))
  {
    out.pop_back();
  }
  return out;
}
}

BenchStats Summarise(std::vector<double> v)
{
  BenchStats s;
  if (v.empty())
  {
    return s;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  s.lo = v.front();
  s.hi = v.back();
  return s;
}

BenchStats TimeRuns(int runs, const std::function<double()>& once)
{
  return TimeInterleaved(runs, { once }).front();
}

std::vector<BenchStats> TimeInterleaved(int runs, const std::vector<std::function<double()>>& each)
{
  for (const auto& f : each)
  {
    f(); // warm-up
  }
  std::vector<std::vector<double>> t(each.size());
  for (int i = 0; i < runs; ++i)
  {
    for (std::size_t k = 0; k < each.size(); ++k)
    {
      t[k].push_back(each[k]());
    }
  }
  std::vector<BenchStats> out;
  for (auto& v : t)
  {
    out.push_back(Summarise(std::move(v)));
  }
  return out;
}

RunInfo ThisRun()
{
  RunInfo r;
  r.source = std::string(ART_DATA_DIR) + "/..";
  r.commit = Shell("git -C '" + r.source + "' rev-parse --short HEAD 2>/dev/null");
  r.cpu = Shell("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'");
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  r.date = date;
  return r;
}

void FinishResults(const std::string& chartScript, const std::string& stem)
{
  const auto r = RunProgram({ "/usr/bin/python3", chartScript, stem + ".json", stem + ".png" }, "");
  if (r.exitCode != 0)
  {
    throw art::Error("the chart script failed", chartScript);
  }
  std::printf("\nresults      %s.json, %s.md, %s.png\n", stem.c_str(), stem.c_str(), stem.c_str());
}
} // namespace cli
