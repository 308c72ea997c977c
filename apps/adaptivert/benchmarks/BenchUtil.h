// BenchUtil: what every benchmark target shares: medians with their min-max over timed runs
// after a warm-up (docs/benchmarks.md), and the machine and commit a result belongs to.
#ifndef adaptivert_BenchUtil_h
#define adaptivert_BenchUtil_h

#include <functional>
#include <string>
#include <vector>

namespace cli
{
struct BenchStats
{
  double median = 0, lo = 0, hi = 0;
};

BenchStats Summarise(std::vector<double> v);
/// One warm-up call, then `runs` calls; each returns the seconds it measured.
BenchStats TimeRuns(int runs, const std::function<double()>& once);
/// Several methods timed in turn: a warm-up call of each, then `runs` rounds of one call of each.
/// A machine whose speed drifts slows them alike, so their ratios hold.
std::vector<BenchStats> TimeInterleaved(int runs, const std::vector<std::function<double()>>& each);
/// What a result belongs to: the source tree (its chart scripts live there), its short commit
/// ("" outside a git checkout), the CPU's model name and the UTC time of the run.
struct RunInfo
{
  std::string source, commit, cpu, date;
};
RunInfo ThisRun();
/// Draws STEM.png from STEM.json with a matplotlib script (throws art::Error naming the script
/// when it fails) and prints where the JSON, markdown table and chart are.
void FinishResults(const std::string& chartScript, const std::string& stem);
} // namespace cli

#endif
