// ReductionWorker: runs the least-squares tet reduction (art::TetReducer) of a volume in a
// std::thread, so the viewer's window stays responsive. The main thread polls its progress and
// takes the nested levels as they are made; no VTK object is touched off the main thread.
#ifndef art_ReductionWorker_h
#define art_ReductionWorker_h

#include "Progress.h"
#include "TetReducer.h"
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
    double Fraction = 0;  ///< overall progress in [0, 1]
    int LevelsReady = 0;  ///< levels made so far (taken or not)
    bool Finished = false;
    double Seconds = 0;   ///< since Start, or the whole run once finished
    std::string Error;    ///< set when the run failed
  };

  /// Takes the voxels (already converted on the main thread) and the budgets, ascending.
  ReductionWorker(art::VoxelVolume volume, std::vector<long long> budgets);
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
  std::atomic<double> Fraction{ 0.0 };
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
