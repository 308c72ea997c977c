// ReductionBenchmark: what `adaptivert bench reduction` measures, side by side in one run: each
// refinement series (bisection, relocated bisection, edge splits, anisotropic) at the paper's
// levels, a separate timed run of each to a share of the voxels as vertices, uniform
// downsampling at each mesh's vertex count and VTK's quadric decimation at the first series'
// tet counts; ReductionReport writes them out.
#ifndef adaptivert_ReductionBenchmark_h
#define adaptivert_ReductionBenchmark_h

#include "benchmarks/BenchUtil.h"

#include <string>
#include <vector>

namespace cli
{
/// One mesh of a series and what it is measured against.
struct ReductionRow
{
  long long level = 0;            ///< the budget (tets)
  long long tets = 0, vertices = 0;
  double rms = 0, max = 0;
  double minDihedral = 0, minRadiusRatio = 0, meanRadiusRatio = 0;
  BenchStats seconds;             ///< build time up to this mesh (cumulative over a run of levels)
  double uniformRms = 0, uniformMax = 0; ///< uniform downsampling at this mesh's vertex count
  long long uniformVertices = 0;
};

struct ReductionSeries
{
  std::string name;               ///< bisection, relocated, edge, anisotropic
  std::vector<ReductionRow> levels;
  BenchStats peakMB;              ///< process peak over the run of levels
  std::vector<ReductionRow> timed; ///< separate runs to a vertex share
  std::vector<BenchStats> timedPeakMB;
};

/// VTK's quadric decimation of the full tetrahedrisation, chained from the largest level down.
struct QuadricRow
{
  long long tets = 0, vertices = 0, uncovered = 0, inverted = 0;
  double rms = -1, max = -1, coveredRms = -1, seconds = 0;
  long long oursTets = 0;          ///< the first series reduced to the quadric's own count ...
  double oursCoveredRms = -1;      ///< ... and measured on the voxels the quadric covers
};

struct ReductionResults
{
  std::string input;
  int dims[3] = { 0, 0, 0 };
  long long voxels = 0;
  double range[2] = { 0, 0 };
  int runs = 1;
  std::vector<ReductionSeries> series;
  bool quadric = false;
  std::vector<QuadricRow> quadricRows; ///< one per level, ascending
  long long quadricInputTets = 0;
  double quadricTetrahedralizeSeconds = 0, quadricPeakMB = 0;
};

/// Writes STEM.json and STEM.md (returned too) for `r`.
std::string WriteReductionReport(const ReductionResults& r, const std::string& stem);
} // namespace cli

#endif
