// ReductionWorker: runs the least-squares tet reduction (art::TetReducer) of a volume in a
// std::thread, so the viewer's window stays responsive. The main thread polls its progress and
// takes the levels as they are made; no VTK object is touched off the main thread.
#ifndef art_ReductionWorker_h
#define art_ReductionWorker_h

#include "Progress.h"
#include "TetReducer.h"
#include "TransferFunction.h"
#include "VoxelVolume.h"

#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace view
{
class ReductionWorker
{
public:
  struct Status
  {
    double Fraction = 0;  ///< progress of the current stage in [0, 1]
    bool Relocating = false; ///< the stage: moving a level's vertices (its own 0 -> 1), else refining
    int LevelsReady = 0;  ///< levels made so far (taken or not)
    bool Finished = false;
    double Seconds = 0;   ///< since Start, or the whole run once finished
    std::string Error;    ///< set when the run failed
  };

  /// Takes the voxels (already converted on the main thread), the budgets, ascending, and the
  /// reducer's other settings (their TargetTets and Levels are the budgets').
  ReductionWorker(art::VoxelVolume volume, std::vector<long long> budgets, art::ReducerOptions options = {});
  /// The settings `adaptivert render` reduces with for a transfer function (composite, no
  /// iso-surface) and a refinement: the fit weighted by its opacity, then, on the lattice, the
  /// vertices relocated (closer to the voxels' picture than the plain lattice fit at the same
  /// tets, for several times the time).
  /// `refinement` is bisection, edge or anisotropic (ViewerOptions checked it).
  static art::ReducerOptions ShowingWith(const art::TransferFunction& tf, const std::string& refinement = "bisection");
  /// Cancels a running reduction and waits for the thread.
  ~ReductionWorker();
  ReductionWorker(const ReductionWorker&) = delete;
  ReductionWorker& operator=(const ReductionWorker&) = delete;

  void Start();
  Status Poll() const;
  /// The levels made since the last call, coarsest first.
  std::vector<art::ReducedMesh> TakeLevels();
  std::size_t NumberOfBudgets() const { return Budgets.size(); }

private:
  void Run();

  art::VoxelVolume Volume;
  std::vector<long long> Budgets;
  art::ReducerOptions Options;
  std::atomic<double> Fraction{ 0.0 };
  std::atomic<bool> Relocating{ false };
  art::Progress Prog;
  mutable std::mutex Lock;
  std::vector<art::ReducedMesh> Ready;
  int Made = 0;
  bool Done = false;
  double Elapsed = 0;
  std::string Failure;
  std::chrono::steady_clock::time_point Begin;
  std::thread Thread;
};
} // namespace view

#endif
