// Bench: `adaptivert bench <what>` runs one registered benchmark target. Each writes into one
// results folder a JSON of raw figures (machine, date, commit), a markdown table and a PNG chart.
#ifndef adaptivert_Bench_h
#define adaptivert_Bench_h

#include "cli/Options.h"

#include <string>
#include <vector>

namespace cli
{
struct BenchTarget
{
  std::string name;    ///< "triangles", "reduction", "tets"
  std::string summary; ///< one line for --help
  void (*declare)(Options&) = nullptr; ///< its own options (names must not clash)
  int (*run)(const Options&) = nullptr;
};

std::vector<BenchTarget>& BenchTargets();

struct BenchRegistrar
{
  explicit BenchRegistrar(BenchTarget t) { BenchTargets().push_back(std::move(t)); }
};
} // namespace cli

#endif
