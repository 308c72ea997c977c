// TetBenchmark: the rows `adaptivert bench tets` measures and the files it writes from them (JSON,
// markdown with the ratios, and the scaling figure: at FixedPoint's own PSNR, the smallest mesh of
// each series that reaches it and its speed against FixedPoint).
#ifndef adaptivert_TetBenchmark_h
#define adaptivert_TetBenchmark_h

#include "benchmarks/BenchUtil.h"
#include "ImageMetrics.h"

#include <string>
#include <vector>

namespace cli
{
struct TetBenchRow
{
  std::string method, mesh;
  std::string series; ///< "reduced", a --tets-series name, "full resolution" or "voxels"
  long long tets = 0, vertices = 0;
  BenchStats seconds;
  art::ImageMetricsResult err;
  double tetsPerRay = 0, nsPerTet = 0;
};

/// What the run was: the volume as loaded (after any resampling) and how it was drawn.
struct TetBenchSetup
{
  std::string input, inputLabel, transferFunction, reduction;
  int dims[3] = { 0, 0, 0 };
  long long voxels = 0;
  double resample = 1;
  int width = 0, height = 0, runs = 0;
  double referenceSeconds = 0;
};

/// The smallest mesh of one series whose exact render (ERT 0.99) reaches FixedPoint's PSNR.
struct TetBenchMatch
{
  std::string series;
  const TetBenchRow* fixedPoint = nullptr;
  const TetBenchRow* mesh = nullptr; ///< nullptr: no mesh of the series reaches it
  const TetBenchRow* largest = nullptr; ///< the series' best PSNR when none reaches it
};

std::vector<TetBenchMatch> MatchFixedPointPsnr(const std::vector<TetBenchRow>& rows);
/// Writes STEM.json and STEM.md; returns the markdown.
std::string WriteTetBenchResults(const std::string& stem, const TetBenchSetup& setup, const std::vector<TetBenchRow>& rows);
} // namespace cli

#endif
