/**
 * @class vtkSurfaceTetrahedralizer
 * @brief Tetrahedralizes the solid a closed surface bounds (TetGen), optionally carrying a volume's values.
 *
 * Input port 0: a vtkPolyData whose polygons and strips (triangulated first) form a closed,
 * manifold surface that does not intersect itself; this is checked before TetGen runs, and a
 * surface that fails is an error naming the count of open or shared edges or crossing triangles.
 * Optional input port 1: a vtkImageData in the same coordinates; the mesh's points then carry its
 * point scalars (or the array given with SetInputArrayToProcess(0, 1, 0, POINTS, name)) fitted to
 * the voxels inside in the least-squares sense, and with TargetTets the tets where the fit misses
 * the voxels most are refined until the budget is met.
 *
 * Output: vtkUnstructuredGrid of VTK_TETRA (quality bounds RadiusEdgeRatio and MinDihedral, TetGen
 * -pq), with the fitted point scalars and cell arrays approximation_error and max_error when a
 * volume is given, and field data surface_volume, mesh_volume, tets, vertices, build_seconds,
 * rms_error and max_error. Set TargetTets or MaxVolume (or give a volume). Progress events
 * between TetGen runs. TetGen is AGPL-3.0: this filter is in AdaptiveRT::Meshing, built only
 * with ART_WITH_GPL_MESHING.
 */
#ifndef vtkSurfaceTetrahedralizer_h
#define vtkSurfaceTetrahedralizer_h

#include "AdaptiveRTMeshingModule.h"
#include "vtkUnstructuredGridAlgorithm.h"

class ADAPTIVERTMESHING_EXPORT vtkSurfaceTetrahedralizer : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkSurfaceTetrahedralizer* New();
  vtkTypeMacro(vtkSurfaceTetrahedralizer, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * About this many tets (0, the default, leaves it unset).
   */
  vtkSetClampMacro(TargetTets, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TargetTets, vtkIdType);

  /**
   * No tet larger than this, in the surface's units cubed (<= 0, the default, leaves it unset).
   */
  vtkSetMacro(MaxVolume, double);
  vtkGetMacro(MaxVolume, double);

  /**
   * TetGen's quality bounds: largest circumradius over shortest edge (default 1.414) and smallest
   * dihedral angle in degrees (default 10).
   */
  vtkSetClampMacro(RadiusEdgeRatio, double, 1.1, 10.0);
  vtkGetMacro(RadiusEdgeRatio, double);
  vtkSetClampMacro(MinDihedral, double, 0.0, 20.0);
  vtkGetMacro(MinDihedral, double);

  /**
   * The volume whose values the points carry (input port 1, optional).
   */
  void SetVolumeConnection(vtkAlgorithmOutput* port) { this->SetInputConnection(1, port); }
  void SetVolumeData(vtkDataObject* image) { this->SetInputData(1, image); }

  /**
   * Figures of the last run (also in the output's field data).
   */
  vtkGetMacro(SurfaceVolume, double);
  vtkGetMacro(MeshVolume, double);
  vtkGetMacro(RMSError, double);

protected:
  vtkSurfaceTetrahedralizer();
  ~vtkSurfaceTetrahedralizer() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType TargetTets = 0;
  double MaxVolume = -1.0;
  double RadiusEdgeRatio = 1.414;
  double MinDihedral = 10.0;
  double SurfaceVolume = 0.0, MeshVolume = 0.0, RMSError = 0.0;

private:
  vtkSurfaceTetrahedralizer(const vtkSurfaceTetrahedralizer&) = delete;
  void operator=(const vtkSurfaceTetrahedralizer&) = delete;
};

#endif
