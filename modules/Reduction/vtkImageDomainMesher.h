/**
 * @class vtkImageDomainMesher
 * @brief Meshes the voxels of a region or a label map with tets whose boundary follows its surface.
 *
 * The object factory's base: vtkAdaptiveTetReducer's SetRegion and SetLabels ask it for the
 * mesh of an art::ImageDomainRequest. This class meshes nothing (IsAvailable() is false and
 * Mesh() throws art::Error saying so); AdaptiveRT::Meshing overrides it with CGAL's Mesh_3
 * (vtkCGALImageDomainMesher), registered when that module is loaded (vtk_module_autoinit, or an
 * import of the Python package), which a build includes when ART_WITH_GPL_MESHING is on.
 */
#ifndef vtkImageDomainMesher_h
#define vtkImageDomainMesher_h

#include "AdaptiveRTReductionModule.h"
#include "ImageDomain.h"
#include "vtkObject.h"

class ADAPTIVERTREDUCTION_EXPORT vtkImageDomainMesher : public vtkObject
{
public:
  static vtkImageDomainMesher* New();
  vtkTypeMacro(vtkImageDomainMesher, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// True when this build can mesh image domains.
  virtual bool IsAvailable() const { return false; }
  /// The mesh of `request`; throws art::Error when it cannot be made (here, always).
  virtual art::ImageDomainMesh Mesh(const art::ImageDomainRequest& request);

protected:
  vtkImageDomainMesher() = default;
  ~vtkImageDomainMesher() override = default;

private:
  vtkImageDomainMesher(const vtkImageDomainMesher&) = delete;
  void operator=(const vtkImageDomainMesher&) = delete;
};

#endif
