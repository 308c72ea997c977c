#include "PieceReduction.h"

#include "Error.h"

#include <vtkCommunicator.h>
#include <vtkExtentTranslator.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>

namespace art
{
namespace
{
// The pilot's budget, as a fraction of the piece's voxel-proportional share: its error ranks the
// pieces well (tests/benchmarks/paraview-results/README.md) at a fraction of the final run's time.
constexpr double PilotFraction = 1.0 / 8.0;
constexpr long long SmallestBudget = 48;
// With an error bound alone, the pilot's budget: a tet per this many voxels.
constexpr long long PilotVoxelsPerTet = 128;

double SquaredError(const ReducedMesh& m, long long voxels)
{
  const double e = m.Weighted ? m.WeightedRms : m.Rms;
  return e * e * double(voxels);
}

// Runs `step` unless this process already failed; an error becomes this process's failure.
template <class F>
void Attempt(std::string& failure, F&& step)
{
  if (!failure.empty())
  {
    return;
  }
  try
  {
    step();
  }
  catch (const std::exception& e)
  {
    failure = e.what();
    if (failure.empty())
    {
      failure = "the reduction failed";
    }
  }
}

// Each piece's RMS bound for a bound `rms` over all voxels: the squared-error budget rms^2 N shared
// in proportion to the pieces' pilot errors, except that no piece is held below rms / 4 (a piece
// of near-constant voxels would otherwise be refined, for nothing, almost to full resolution);
// such pieces get that floor and the others share what is left. Every process computes the same.
std::vector<double> RmsBounds(double rms, const std::vector<double>& errors, const std::vector<double>& voxels)
{
  const double floor2 = rms * rms / 16.0;
  std::vector<double> bound2(errors.size(), -1.0);
  for (bool fixedOne = true; fixedOne;)
  {
    fixedOne = false;
    double budget = rms * rms * std::accumulate(voxels.begin(), voxels.end(), 0.0), shared = 0;
    for (size_t p = 0; p < errors.size(); ++p)
    {
      if (bound2[p] >= 0)
      {
        budget -= bound2[p] * voxels[p];
      }
      else
      {
        shared += errors[p];
      }
    }
    for (size_t p = 0; p < errors.size(); ++p)
    {
      if (bound2[p] < 0 && voxels[p] > 0 && shared > 0 && budget * errors[p] / (shared * voxels[p]) < floor2)
      {
        bound2[p] = floor2;
        fixedOne = true;
      }
    }
    if (!fixedOne)
    {
      for (size_t p = 0; p < errors.size(); ++p)
      {
        if (bound2[p] < 0)
        {
          bound2[p] = voxels[p] > 0 && shared > 0 ? std::max(0.0, budget) * errors[p] / (shared * voxels[p]) : rms * rms;
        }
      }
    }
  }
  std::vector<double> bounds(errors.size());
  std::transform(bound2.begin(), bound2.end(), bounds.begin(), [](double b2) { return std::sqrt(b2); });
  return bounds;
}

void ThrowIfAnyFailed(double failed, const std::string& failure)
{
  if (failed > 0)
  {
    throw Error(failure.empty() ? "another piece of the volume could not be reduced" : failure);
  }
}
} // namespace

void PieceExtent(const int whole[6], int piece, int pieces, int extent[6])
{
  int w[6], e[6];
  std::copy(whole, whole + 6, w);
  vtkNew<vtkExtentTranslator> split;
  split->PieceToExtentThreadSafe(piece, pieces, 0, w, e, vtkExtentTranslator::BLOCK_MODE, 0);
  std::copy(e, e + 6, extent);
}

bool HoldsVoxels(const int whole[6], const int extent[6])
{
  bool holds = true;
  for (int a = 0; a < 3; ++a)
  {
    holds = holds && extent[2 * a] <= extent[2 * a + 1] &&
      (extent[2 * a] < extent[2 * a + 1] || whole[2 * a] == whole[2 * a + 1]);
  }
  return holds;
}

namespace
{
bool Contains(const int outer[6], const int inner[6])
{
  for (int a = 0; a < 3; ++a)
  {
    if (outer[2 * a] > inner[2 * a] || outer[2 * a + 1] < inner[2 * a + 1])
    {
      return false;
    }
  }
  return true;
}

std::string ExtentText(const int* e)
{
  std::string t;
  for (int i = 0; i < 6; ++i)
  {
    t += (i ? " " : "") + std::to_string(e[i]);
  }
  return t;
}

// A shallow copy of `image` cropped to `extent` (Crop replaces the copy's arrays only).
vtkSmartPointer<vtkImageData> Cropped(vtkImageData* image, const int extent[6])
{
  auto part = vtkSmartPointer<vtkImageData>::New();
  part->ShallowCopy(image);
  int have[6];
  image->GetExtent(have);
  if (!std::equal(have, have + 6, extent))
  {
    part->Crop(extent);
  }
  return part;
}

constexpr int PartTag = 736301;
} // namespace

vtkSmartPointer<vtkImageData> OwnPart(vtkMultiProcessController* controller, vtkImageData* input, const int whole[6],
  int piece, int pieces, int given[6], std::string& failure)
{
  int ext[6];
  PieceExtent(whole, piece, pieces, ext);
  const int none[6] = { 0, -1, 0, -1, 0, -1 };
  std::copy(none, none + 6, given);
  if (input)
  {
    input->GetExtent(given);
  }
  const bool needs = HoldsVoxels(whole, ext);
  int mine = !needs || (input && Contains(given, ext)) ? 1 : 0;
  std::vector<int> all(static_cast<size_t>(pieces), 0);
  controller->AllGather(&mine, all.data(), 1);
  if (std::find(all.begin(), all.end(), 0) == all.end())
  {
    return needs ? Cropped(input, ext) : vtkSmartPointer<vtkImageData>::New();
  }
  // Process 0 hands out the parts of those that lack theirs, with their placement (the transfer
  // keeps the arrays; extent, origin, spacing and direction go beside them).
  int canServe = piece == 0 && input && Contains(given, whole) ? 1 : 0;
  controller->Broadcast(&canServe, 1, 0);
  if (!canServe)
  {
    failure = "piece " + std::to_string(piece) + " of " + std::to_string(pieces) + ": the input holds the extent " +
      ExtentText(given) + (mine ? "" : ", not all of " + ExtentText(ext)) +
      ", and piece 0 does not hold the whole volume to hand out the parts";
    return nullptr;
  }
  if (piece == 0)
  {
    for (int p = 1; p < pieces; ++p)
    {
      if (!all[static_cast<size_t>(p)])
      {
        int e[6];
        PieceExtent(whole, p, pieces, e);
        vtkSmartPointer<vtkImageData> part = Cropped(input, e);
        double place[15];
        part->GetOrigin(place);
        part->GetSpacing(place + 3);
        std::copy(part->GetDirectionMatrix()->GetData(), part->GetDirectionMatrix()->GetData() + 9, place + 6);
        controller->Send(e, 6, p, PartTag);
        controller->Send(place, 15, p, PartTag);
        controller->Send(part, p, PartTag);
      }
    }
    return Cropped(input, ext);
  }
  if (mine)
  {
    return needs ? Cropped(input, ext) : vtkSmartPointer<vtkImageData>::New();
  }
  int e[6];
  double place[15];
  auto part = vtkSmartPointer<vtkImageData>::New();
  controller->Receive(e, 6, 0, PartTag);
  controller->Receive(place, 15, 0, PartTag);
  controller->Receive(part, 0, PartTag);
  part->SetExtent(e);
  part->SetOrigin(place);
  part->SetSpacing(place + 3);
  part->SetDirectionMatrix(place + 6);
  return part;
}

bool OnePiecePerProcess(vtkMultiProcessController* controller, int piece, int pieces)
{
  return controller && pieces > 1 && controller->GetNumberOfProcesses() == pieces &&
    controller->GetLocalProcessId() == piece;
}

void PieceReduction::Sum(std::vector<double>& values) const
{
  std::vector<double> out(values.size());
  this->Controller->AllReduce(values.data(), out.data(), static_cast<vtkIdType>(values.size()), vtkCommunicator::SUM_OP);
  values = out;
}

void PieceReduction::Maximum(std::vector<double>& values) const
{
  std::vector<double> out(values.size());
  this->Controller->AllReduce(values.data(), out.data(), static_cast<vtkIdType>(values.size()), vtkCommunicator::MAX_OP);
  values = out;
}

std::vector<ReducedMesh> PieceReduction::Run(const ReducerOptions& options, const VoxelVolume* piece,
  const std::string& failure, Progress* pilotProgress, Progress* progress, PieceFigures& figures) const
{
  std::string failed = piece ? failure : (failure.empty() ? "the piece could not be read" : failure);
  const long long voxels = piece && failed.empty() ? piece->NumberOfVoxels() : 0;
  const bool holdsVoxels = voxels > 0;

  // 1. Every piece is ready; the whole volume's voxels and range.
  std::vector<double> sums = { failed.empty() ? 0.0 : 1.0, double(voxels) };
  std::vector<double> ends = { holdsVoxels ? piece->Range[1] : -HUGE_VAL, holdsVoxels ? -piece->Range[0] : -HUGE_VAL };
  this->Sum(sums);
  this->Maximum(ends);
  ThrowIfAnyFailed(sums[0], failed);
  const double allVoxels = sums[1];
  figures.Range[0] = -ends[1];
  figures.Range[1] = ends[0];
  ReducerOptions opt = options;
  if (opt.TargetError >= 0 && opt.ErrorRelative)
  {
    opt.TargetError *= figures.Range[1] - figures.Range[0];
    opt.ErrorRelative = false;
  }
  figures.Budget = options.TargetTets;
  figures.Bound = opt.TargetError;

  // 2. The budgets are shared out by each piece's squared error at a pilot run: the tets, and an
  //    RMS bound's squared error over all voxels.
  figures.Share = allVoxels > 0 ? double(voxels) / allVoxels : 0.0;
  const bool shareTets = options.TargetTets > 0;
  const bool shareError = opt.TargetError >= 0 && opt.ErrorMetric == ReducerOptions::Metric::RMS;
  if (shareTets || shareError)
  {
    double error = 0;
    Attempt(failed, [&] {
      if (!holdsVoxels)
      {
        return;
      }
      ReducerOptions pilot = opt;
      pilot.TargetTets = std::max(SmallestBudget,
        shareTets ? std::llround(PilotFraction * double(options.TargetTets) * figures.Share) : voxels / PilotVoxelsPerTet);
      pilot.TargetError = -1;
      pilot.Levels.clear();
      pilot.RelocateVertices = false; // 4-5 x the time (TetReducer.h) for a ranking of pieces
      const std::vector<ReducedMesh> m = TetReducer(pilot).Run(*piece, pilotProgress);
      error = SquaredError(m.back(), voxels);
      figures.PilotSeconds = m.back().BuildSeconds;
    });
    // Every piece's error and voxels, on every process (each adds its own at its index).
    const int pieces = this->Controller->GetNumberOfProcesses(), me = this->Controller->GetLocalProcessId();
    std::vector<double> all(1 + 2 * static_cast<size_t>(pieces), 0.0);
    all[0] = failed.empty() ? 0.0 : 1.0;
    all[1 + me] = error;
    all[1 + pieces + me] = double(voxels);
    this->Sum(all);
    ThrowIfAnyFailed(all[0], failed);
    const std::vector<double> errors(all.begin() + 1, all.begin() + 1 + pieces);
    const std::vector<double> counts(all.begin() + 1 + pieces, all.end());
    const double total = std::accumulate(errors.begin(), errors.end(), 0.0);
    if (total > 0)
    {
      figures.Share = error / total;
    }
    if (shareTets)
    {
      auto share = [&](long long budget) { return std::max(SmallestBudget, std::llround(double(budget) * figures.Share)); };
      opt.TargetTets = share(options.TargetTets);
      opt.Levels.clear();
      for (long long level : options.Levels)
      {
        const long long l = share(level);
        if (l < opt.TargetTets && std::find(opt.Levels.begin(), opt.Levels.end(), l) == opt.Levels.end())
        {
          opt.Levels.push_back(l);
        }
      }
    }
    if (shareError && total > 0)
    {
      opt.TargetError = RmsBounds(opt.TargetError, errors, counts)[static_cast<size_t>(me)];
    }
  }
  figures.TargetError = opt.TargetError;
  figures.TargetTets = opt.TargetTets;

  // 3. This piece's reduction; the whole volume's errors from every piece's.
  std::vector<ReducedMesh> meshes;
  Attempt(failed, [&] {
    if (holdsVoxels)
    {
      meshes = TetReducer(opt).Run(*piece, progress);
    }
  });
  const ReducedMesh* last = meshes.empty() ? nullptr : &meshes.back();
  sums = { failed.empty() ? 0.0 : 1.0, last ? last->Rms * last->Rms * double(voxels) : 0.0,
    last ? last->WeightedRms * last->WeightedRms * double(voxels) : 0.0, last ? double(last->NumberOfTets()) : 0.0,
    last && !last->TargetReached ? 1.0 : 0.0 };
  ends = { last ? last->Max : 0.0, last ? last->WeightedMax : 0.0 };
  this->Sum(sums);
  this->Maximum(ends);
  ThrowIfAnyFailed(sums[0], failed);
  figures.Rms = allVoxels > 0 ? std::sqrt(sums[1] / allVoxels) : 0.0;
  figures.WeightedRms = allVoxels > 0 ? std::sqrt(sums[2] / allVoxels) : 0.0;
  figures.Tets = std::llround(sums[3]);
  figures.Reached = sums[4] == 0;
  figures.Max = ends[0];
  figures.WeightedMax = ends[1];
  return meshes;
}
} // namespace art
