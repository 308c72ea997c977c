/**
 * @class vtkAdaptiveTetReducer
 * @brief Reduces a volume (vtkImageData) to an adaptive tetrahedral grid by least squares.
 *
 * The multilevel finite-element reducer of Grosso, Luerig & Ertl (Vis '97): a coarse conforming
 * tetrahedrisation of the volume's box is refined by newest-vertex bisection where the best
 * piecewise-linear (L2) fit of the voxels is worst, until TargetTets or TargetError is met
 * (whichever is set; with both, whichever comes first). SetRefinementToAnisotropic() remeshes
 * the box with MMG3D to the voxels' Hessian metric instead (see SetRefinement).
 *
 * Output port 0: vtkUnstructuredGrid of VTK_TETRA with point scalars named like the input (the
 * fit at each vertex; double for double, 32- and 64-bit integer input, else float), cell arrays "approximation_error" (RMS over the voxels a tet owns) and
 * "max_error", and field data rms_error, max_error, tets, vertices, build_seconds,
 * target_tets, target_error and source_spacing (the input's mean voxel spacing, which a
 * transfer-function preset's opacity unit distance follows). Output port 1: a vtkMultiBlockDataSet holding one such grid per
 * level added with AddLevel (a series from one run, coarsest first; nested unless relocated or
 * anisotropic) and the final grid
 * (GetOutputDataObject(1); GetOutput(1) casts it to a grid and gives null, from Python None).
 *
 * The reduced array is the point scalars (without them the first one-component point array, as
 * `adaptivert reduce` takes it), or the one given with SetInputArrayToProcess(0, 0, 0,
 * vtkDataObject::FIELD_ASSOCIATION_POINTS, name). Values on the cells (the cell scalars of an image
 * without point arrays, or a cell array given with FIELD_ASSOCIATION_CELLS) are one voxel per cell
 * at its centre, as the file loader reads them: the mesh spans the cell centres.
 * The input needs one scalar component and at least 2 voxels along each axis; any scalar type,
 * spacing, origin and direction. Progress events are fired between refinement levels.
 * Pieces: under a request for piece p of n with a Controller of n processes, this being process
 * p (pvbatch or pvserver under MPI), each process asks for and reduces only its part of the
 * extent (VTK's block split; neighbours share a layer of voxels, so their meshes meet without a
 * gap, though not vertex to vertex), and the tet budget and levels are shared out by each part's
 * error (art::PieceReduction): no process holds the whole volume. The field data's errors, range
 * and total_tets are then the whole volume's; tets, vertices, piece_target_tets,
 * piece_target_error, piece_pilot_seconds, piece_extent (reduced) and input_extent (given) this
 * piece's.
 * Serial (piece 0 of 1), or pieces without such a controller (a writer streaming pieces in one
 * process): the whole extent is read as one piece, piece 0 holds the mesh, the others are empty.
 */
#ifndef vtkAdaptiveTetReducer_h
#define vtkAdaptiveTetReducer_h

#include "AdaptiveRTReductionModule.h"
#include "vtkSmartPointer.h" // SelectVoxels
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // SelectVoxels
#include <vector>

class vtkAlgorithmOutput;
class vtkDataObject;
class vtkImageData;
class vtkMultiBlockDataSet;
class vtkMultiProcessController;
class vtkPiecewiseFunction;
class vtkUnstructuredGrid;
namespace art
{
class Progress;
struct ReducedMesh;
struct ReducerOptions;
struct VoxelVolume;
}

class ADAPTIVERTREDUCTION_EXPORT vtkAdaptiveTetReducer : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkAdaptiveTetReducer* New();
  vtkTypeMacro(vtkAdaptiveTetReducer, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ErrorMetrics
  {
    RMS = 0,
    MAX = 1
  };

  /**
   * Stop at this many tetrahedra (0, the default, leaves it unset).
   */
  vtkSetClampMacro(TargetTets, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TargetTets, vtkIdType);

  /**
   * Stop once the global error is at most this (negative, the default, leaves it unset). In
   * data units, or as a fraction of the scalar range when ErrorRelative is on.
   */
  vtkSetMacro(TargetError, double);
  vtkGetMacro(TargetError, double);

  /**
   * Which global error TargetError bounds: RMS (default) or MAX over all voxels.
   */
  vtkSetClampMacro(ErrorMetric, int, RMS, MAX);
  vtkGetMacro(ErrorMetric, int);
  void SetErrorMetricToRMS() { this->SetErrorMetric(RMS); }
  void SetErrorMetricToMax() { this->SetErrorMetric(MAX); }

  vtkSetMacro(ErrorRelative, bool);
  vtkGetMacro(ErrorRelative, bool);
  vtkBooleanMacro(ErrorRelative, bool);

  /**
   * Growth of the tet count per refinement level (0.2: 20% more tets per re-fit). 0 (the
   * default): with bisection 0.5 while under a quarter of the next budget, then 0.2; 0.2 with
   * edge splits.
   */
  vtkSetClampMacro(RefineFraction, double, 0.0, 4.0);
  vtkGetMacro(RefineFraction, double);

  /**
   * Clamp each output value to the range of the voxels under its vertex's tets (default off):
   * no overshoot beyond the data at sharp edges, which maximum-intensity projection shows as
   * bright facets, for a slightly larger L2 error.
   */
  vtkSetMacro(ClampToVoxels, bool);
  vtkGetMacro(ClampToVoxels, bool);
  vtkBooleanMacro(ClampToVoxels, bool);

  /**
   * Move each output mesh's vertices off the bisection lattice to lower their star's error, then
   * refit (default off): vertices settle on sharp surfaces and the RMS falls at the same tets;
   * tets get flatter (shape floor 0.2), the levels on port 1 are no longer nested, and the
   * reduction is far slower.
   */
  vtkSetMacro(RelocateVertices, bool);
  vtkGetMacro(RelocateVertices, bool);
  vtkBooleanMacro(RelocateVertices, bool);

  /**
   * Relative residual at which conjugate gradients stops.
   */
  vtkSetClampMacro(SolverTolerance, double, 1e-15, 1e-2);
  vtkGetMacro(SolverTolerance, double);

  enum RefinementModes
  {
    BISECTION = 0,
    EDGE_SPLIT = 1,
    ANISOTROPIC = 2
  };
  /**
   * How the mesh is made: BISECTION (default), newest-vertex bisection with near-isotropic
   * shapes; EDGE_SPLIT, the edges whose split removes the most error per added tet are split with
   * every tet around them (thin tets along sharp surfaces, much flatter tets, slower);
   * ANISOTROPIC, MMG3D remeshes the box to the voxels' Hessian metric (tets long along surfaces
   * and thin across them; far lower error per vertex on a CT), TargetTets met within 5%. The
   * levels on port 1 are then each adapted anew, not nested, and TargetError grows the budget
   * until it is met. Needs MMG's libmmg3d at run time (an error says so when it is missing).
   */
  vtkSetClampMacro(Refinement, int, BISECTION, ANISOTROPIC);
  vtkGetMacro(Refinement, int);
  void SetRefinementToBisection() { this->SetRefinement(BISECTION); }
  void SetRefinementToEdgeSplit() { this->SetRefinement(EDGE_SPLIT); }
  void SetRefinementToAnisotropic() { this->SetRefinement(ANISOTROPIC); }

  enum VectorModeType
  {
    DISABLED = -1, ///< a vector array is an error
    MAGNITUDE = 0, ///< reduce each tuple's Euclidean norm
    COMPONENT = 1  ///< reduce component VectorComponent
  };
  ///@{
  /**
   * What to reduce of an array of several components (a velocity, an RGB volume), as
   * vtkSmartVolumeMapper and vtkTetRayCastMapper draw it: MAGNITUDE, COMPONENT VectorComponent
   * (0-based), or DISABLED (the default: such an array is an error naming these settings).
   */
  vtkSetClampMacro(VectorMode, int, DISABLED, COMPONENT);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, 3);
  vtkGetMacro(VectorComponent, int);
  ///@}

  /**
   * Nested budgets (tet counts) emitted on output port 1 from the same run.
   */
  void AddLevel(vtkIdType tets);
  void RemoveAllLevels();
  int GetNumberOfLevels() const { return static_cast<int>(this->Levels.size()); }
  vtkIdType GetLevel(int i) const;

  /**
   * Reduce for what a transfer function shows: voxels weigh by the slope of this scalar-opacity
   * function over their neighbourhood's scalar range (and the fit's), so tets go where opacity
   * changes. nullptr (the default) is the plain L2 reduction. Field data then also holds
   * weighted_rms_error and weighted_max_error beside the plain errors.
   */
  void SetScalarOpacity(vtkPiecewiseFunction* f);
  vtkGetObjectMacro(ScalarOpacity, vtkPiecewiseFunction);

  /**
   * With a ScalarOpacity: iso-values a renderer draws over it. Voxels next to one weigh as much
   * as the steepest opacity ramp, so the fit places those surfaces where the opacity alone would
   * not ask for tets (a skin iso-surface over a bone transfer function; see
   * art::ReducerOptions::IsoValues).
   */
  void AddIsoValue(double value);
  void RemoveAllIsoValues();
  int GetNumberOfIsoValues() const { return static_cast<int>(this->IsoValues.size()); }
  double GetIsoValue(int i) const;

  /**
   * With a ScalarOpacity: clamp an output value to the range of the voxels under its vertex's
   * tets when its opacity exceeds every opacity those voxels have (default on). The fit's
   * overshoot past thin bright structures otherwise renders as opaque speckles (see
   * art::ReducerOptions::CapOpacity).
   */
  vtkSetMacro(CapOpacity, bool);
  vtkGetMacro(CapOpacity, bool);
  vtkBooleanMacro(CapOpacity, bool);

  /**
   * Least voxel weight of the opacity-weighted reduction, in (0, 1] (default 0.02).
   */
  vtkSetClampMacro(ImportanceFloor, double, 1e-6, 1.0);
  vtkGetMacro(ImportanceFloor, double);

  /**
   * Neighbourhood radius (voxels) whose scalar range sets a voxel's weight (default 2: 5^3).
   */
  vtkSetClampMacro(ImportanceRadius, int, 0, 8);
  vtkGetMacro(ImportanceRadius, int);

  ///@{
  /**
   * Mesh only the voxels whose value lies in [lo, hi] (the bone of a CT, the brain of an MRI):
   * the mesh's boundary follows that region's surface (where the trilinear interpolant crosses
   * lo or hi), pieces of fewer than MinimumIslandVoxels voxels are dropped, the voxels inside are
   * fitted in the least-squares sense, and the region is meshed again to a size field adapted to
   * the fit's error until TargetTets or TargetError (RMS inside the region) is met. The levels
   * of AddLevel do not apply. Meshed by CGAL's Mesh_3 (AdaptiveRT::Meshing, in builds with
   * ART_WITH_GPL_MESHING; otherwise the filter reports an error saying so). RemoveRegion goes
   * back to the whole box. Field data then also hold region_low, region_high, region_voxels,
   * covered_voxels, region_pieces, islands_dropped, island_voxels and meshings.
   */
  void SetRegion(double lo, double hi);
  void RemoveRegion();
  vtkGetVector2Macro(Region, double);
  vtkGetMacro(UseRegion, bool);
  ///@}

  ///@{
  /**
   * The region's range and whether it is meshed, set apart (as ParaView's properties set them):
   * SetRegionRange keeps UseRegion as it is; SetUseRegion(true) meshes the range last set.
   */
  void SetRegionRange(double lo, double hi);
  void SetUseRegion(bool use);
  ///@}

  /**
   * The input is a label map (integer values): one conforming multi-material mesh of every label
   * but the Background, each tet tagged in the cell array "label", the interfaces between labels
   * shared faces; to TargetTets (default off). Meshed by CGAL's Mesh_3, like SetRegion.
   */
  vtkSetMacro(Labels, bool);
  vtkGetMacro(Labels, bool);
  vtkBooleanMacro(Labels, bool);

  ///@{
  /**
   * With Labels: a volume of the same dimensions (an MRI beside its segmentation), on the
   * optional input port 1, whose active point scalars (one component) are fitted inside the
   * labels in the least-squares sense: the output then carries them as point scalars, the RMS and
   * max error inside the labels, and their statistics (source_window) for a default transfer
   * function, as `adaptivert reduce --labels --values` writes them. As vtkProbeFilter takes its
   * source: SetValuesConnection for a pipeline, SetValuesData for a data set (nullptr removes it).
   */
  void SetValuesConnection(vtkAlgorithmOutput* output);
  void SetValuesData(vtkDataObject* values);
  vtkDataObject* GetValuesData();
  ///@}

  /**
   * The label a label map leaves unmeshed (default 0).
   */
  vtkSetMacro(Background, vtkIdType);
  vtkGetMacro(Background, vtkIdType);

  /**
   * With SetRegion or Labels: connected pieces (26-neighbours) of fewer voxels are dropped (an
   * island of a label inside another takes that label). -1 (the default): 27 or 0.01% of the
   * region's voxels, whichever is larger.
   */
  vtkSetClampMacro(MinimumIslandVoxels, vtkIdType, -1, VTK_ID_MAX);
  vtkGetMacro(MinimumIslandVoxels, vtkIdType);

  /**
   * With SetRegion: also reduce the whole box (the default reducer) until its RMS inside the
   * region is as low, and put the tets it needed in field data whole_box_tets (default off: it
   * takes longer than the region's own reduction).
   */
  vtkSetMacro(CompareWholeBox, bool);
  vtkGetMacro(CompareWholeBox, bool);
  vtkBooleanMacro(CompareWholeBox, bool);

  /**
   * Region figures of the last run: voxels meshed, islands dropped, whole-box tets of equal error
   * (0 unless CompareWholeBox).
   */
  vtkGetMacro(RegionVoxels, vtkIdType);
  vtkGetMacro(IslandsDropped, vtkIdType);
  vtkGetMacro(WholeBoxTets, vtkIdType);

  /**
   * Figures of the last run (also in the output's field data).
   */
  vtkGetMacro(RMSError, double);
  vtkGetMacro(MaxError, double);
  vtkGetMacro(BuildSeconds, double);
  vtkGetMacro(WeightedRMSError, double);
  vtkGetMacro(WeightedMaxError, double);

  /**
   * The processes among which pieces are shared (default: the global controller, as ParaView and
   * vtkMPIController set it; none in a serial program).
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

  vtkMTimeType GetMTime() override;

protected:
  vtkAdaptiveTetReducer();
  ~vtkAdaptiveTetReducer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TargetTets = 0;
  double TargetError = -1.0;
  int ErrorMetric = RMS;
  bool ErrorRelative = false;
  bool ClampToVoxels = false;
  bool CapOpacity = true;
  bool RelocateVertices = false;
  double RefineFraction = 0.0;
  double SolverTolerance = 1e-8;
  int Refinement = BISECTION;
  int VectorMode = DISABLED;
  int VectorComponent = 0;
  std::vector<vtkIdType> Levels;
  std::vector<double> IsoValues;
  double RMSError = 0.0, MaxError = 0.0, BuildSeconds = 0.0;
  double WeightedRMSError = 0.0, WeightedMaxError = 0.0;
  vtkPiecewiseFunction* ScalarOpacity = nullptr;
  vtkMultiProcessController* Controller = nullptr;
  double ImportanceFloor = 0.02;
  int ImportanceRadius = 2;
  bool UseRegion = false, Labels = false, CompareWholeBox = false;
  double Region[2] = { 0.0, 0.0 };
  vtkIdType Background = 0, MinimumIslandVoxels = -1;
  vtkIdType RegionVoxels = 0, IslandsDropped = 0, WholeBoxTets = 0;

#ifndef __VTK_WRAP__
  /// The SetRegion / Labels path of RequestData (vtkAdaptiveTetReducerRegion.cxx): throws art::Error.
  void RequestRegion(vtkImageData* input, const art::VoxelVolume& volume, vtkImageData* values, bool asDouble,
    vtkUnstructuredGrid* output, vtkMultiBlockDataSet* levels, art::Progress& progress);
#endif

private:
  /**
   * The image whose point scalars are the one-component voxels to reduce (the array chosen, cell
   * values as voxels at the cells' centres, a vector's magnitude or component); null, with
   * `error` saying why, when there is none.
   */
  vtkSmartPointer<vtkImageData> SelectVoxels(vtkImageData* input, bool& onCells, std::string& error);
  /** The reduction's options from the properties; false (after an error) when they cannot be met. */
  bool MakeOptions(art::ReducerOptions& opt);
  /** The last mesh on port 0, every mesh as a block of port 1, the figures of the last. */
  void WriteMeshes(const std::vector<art::ReducedMesh>& meshes, const std::vector<long long>& levels,
    vtkImageData* input, bool asDouble, vtkUnstructuredGrid* output, vtkMultiBlockDataSet* blocks);

  vtkAdaptiveTetReducer(const vtkAdaptiveTetReducer&) = delete;
  void operator=(const vtkAdaptiveTetReducer&) = delete;
};

#endif
