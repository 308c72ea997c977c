// PieceReduction: one reduction of a volume split into pieces, one piece per process (pvbatch
// under MPI): each process reduces only the voxels of its piece, and the tet budget is shared
// out by each piece's error, as a reduction of the whole volume sends its tets where the error
// is. A pilot run (at an eighth of a voxel-proportional tet budget, or a tet per 128 voxels for an
// error bound alone) measures each piece's (weighted) squared error; an MPI sum
// (vtkMultiProcessController::AllReduce) gives every piece its share of the tets and levels, and
// of an RMS bound's squared-error budget over all voxels (no piece below a quarter of the bound),
// so the pieces' errors together meet it. A maximum bound is every piece's own; a relative bound
// is taken of the whole volume's range.
// Neighbouring pieces share one layer of voxels, so their meshes meet without a gap; they need
// not match there. Every process takes part in every exchange, a failed one too, so that one
// piece's error fails all of them instead of leaving the others waiting. A source that cannot
// read a part is read whole by process 0, which sends each other process its part.
#ifndef art_PieceReduction_h
#define art_PieceReduction_h

#include "AdaptiveRTReductionModule.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkImageData;
class vtkMultiProcessController;

namespace art
{
class Progress;

/// The figures of the whole volume after a piece reduction (every process gets the same).
struct PieceFigures
{
  double Rms = 0, Max = 0, WeightedRms = 0, WeightedMax = 0; ///< over every piece's voxels
  double Range[2] = { 0, 0 }; ///< the whole volume's scalar range
  long long Tets = 0;         ///< of every piece's final mesh
  long long Budget = 0;       ///< the whole tet budget (0: none)
  double Bound = -1;          ///< the whole error bound, data units (< 0: none)
  bool Reached = true;        ///< every piece met its bound
  long long TargetTets = 0;   ///< this piece's share of the budget (0: none)
  double TargetError = -1;    ///< this piece's error bound, data units (< 0: none)
  double Share = 1;           ///< this piece's fraction of the budget
  double PilotSeconds = 0;    ///< this process's pilot run
  int Extent[6] = { 0, -1, 0, -1, 0, -1 };      ///< the extent this piece reduced (the caller's)
  int InputExtent[6] = { 0, -1, 0, -1, 0, -1 }; ///< the extent its input held (the caller's)
};

/// The extent of `piece` of `pieces` in `whole` (VTK's block split, by cells, so that neighbours
/// share a layer of points). Empty (min > max on an axis) when there are more pieces than cells.
ADAPTIVERTREDUCTION_EXPORT void PieceExtent(const int whole[6], int piece, int pieces, int extent[6]);

/// Does the piece `extent` of `whole` hold voxels to reduce (two or more along every axis the
/// whole has two or more)? Thinner pieces (more pieces than cells) add nothing.
ADAPTIVERTREDUCTION_EXPORT bool HoldsVoxels(const int whole[6], const int extent[6]);

/// Collective: this process's part of the image (PieceExtent of `whole`), cropped from `input`
/// when that holds it; else sent by process 0, which holds the whole image (a source that cannot
/// read a part gives piece 0 all of it and the others nothing). Null on every process, with
/// `failure`, when a process lacks its part and process 0 cannot hand it out. `given` is the
/// extent `input` held.
ADAPTIVERTREDUCTION_EXPORT vtkSmartPointer<vtkImageData> OwnPart(vtkMultiProcessController* controller,
  vtkImageData* input, const int whole[6], int piece, int pieces, int given[6], std::string& failure);

/// Does `controller` run one process per piece, this process being `piece` of `pieces`?
ADAPTIVERTREDUCTION_EXPORT bool OnePiecePerProcess(vtkMultiProcessController* controller, int piece, int pieces);

class ADAPTIVERTREDUCTION_EXPORT PieceReduction
{
public:
  explicit PieceReduction(vtkMultiProcessController* controller) : Controller(controller) {}

  /// Collective: every process calls it. `piece` is this process's voxels (none: a piece thinner
  /// than two voxels along an axis, which adds nothing), or null with `failure` saying why this
  /// process cannot reduce. Returns this piece's meshes (as TetReducer::Run; empty for an empty
  /// piece) and fills `figures`. Throws art::Error when any process failed: this one's own
  /// message, or that another piece failed.
  std::vector<ReducedMesh> Run(const ReducerOptions& options, const VoxelVolume* piece, const std::string& failure,
    Progress* pilotProgress, Progress* progress, PieceFigures& figures) const;

private:
  /// Sums `values` over the processes; values[0] counts the failed ones.
  void Sum(std::vector<double>& values) const;
  void Maximum(std::vector<double>& values) const;

  vtkMultiProcessController* Controller;
};
} // namespace art

#endif
