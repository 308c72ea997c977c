#include "ReductionWorker.h"

#include "Error.h"

#include <exception>

namespace view
{
ReductionWorker::ReductionWorker(
  art::VoxelVolume volume, std::vector<long long> budgets, art::ReducerOptions options)
  : Volume(std::move(volume))
  , Budgets(std::move(budgets))
  , Options(std::move(options))
  , Prog([this](double f, const std::string& stage) {
    this->Relocating = stage == "relocate";
    this->Fraction = f;
  })
{
}

ReductionWorker::~ReductionWorker()
{
  Prog.Cancel();
  if (Thread.joinable())
  {
    Thread.join();
  }
}

art::ReducerOptions ReductionWorker::ShowingWith(const art::TransferFunction& tf, const std::string& refinement)
{
  using R = art::ReducerOptions::Refinement;
  art::ReducerOptions opt;
  opt.ScalarOpacity = tf.OpacityPoints();
  opt.Refine = refinement == "anisotropic" ? R::Anisotropic : refinement == "edge" ? R::EdgeSplit : R::Bisection;
  opt.RelocateVertices = opt.Refine != R::Anisotropic;
  return opt;
}

void ReductionWorker::Start()
{
  Begin = std::chrono::steady_clock::now();
  Thread = std::thread([this] { this->Run(); });
}

void ReductionWorker::Run()
{
  art::ReducerOptions opt = Options;
  opt.TargetTets = Budgets.back();
  opt.Levels.assign(Budgets.begin(), Budgets.end() - 1);
  std::string failure;
  try
  {
    art::TetReducer(opt).Run(Volume, &Prog, [this](const art::ReducedMesh& m) {
      std::lock_guard<std::mutex> g(Lock);
      Ready.push_back(m);
      ++Made;
    });
  }
  catch (const std::exception& e)
  {
    failure = e.what();
  }
  std::lock_guard<std::mutex> g(Lock);
  Failure = Prog.Cancelled() ? std::string() : failure;
  Elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - Begin).count();
  Done = true;
}

ReductionWorker::Status ReductionWorker::Poll() const
{
  std::lock_guard<std::mutex> g(Lock);
  Status s;
  s.Fraction = Done ? 1.0 : Fraction.load();
  s.Relocating = !Done && Relocating.load();
  s.LevelsReady = Made;
  s.Finished = Done;
  s.Error = Failure;
  s.Seconds = Done ? Elapsed : std::chrono::duration<double>(std::chrono::steady_clock::now() - Begin).count();
  return s;
}

std::vector<art::ReducedMesh> ReductionWorker::TakeLevels()
{
  std::lock_guard<std::mutex> g(Lock);
  std::vector<art::ReducedMesh> out;
  out.swap(Ready);
  return out;
}
} // namespace view
