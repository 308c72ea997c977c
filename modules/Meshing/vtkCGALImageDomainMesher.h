/**
 * @class vtkCGALImageDomainMesher
 * @brief vtkImageDomainMesher by CGAL's Mesh_3: Delaunay refinement of image domains.
 *
 * Meshes a region of a gray image (where the trilinear interpolant lies in [Lo, Hi], found with
 * Labeled_mesh_domain_3::create_gray_image_mesh_domain and a range functor) or a label map
 * (create_labeled_image_mesh_domain, one subdomain per label, the interfaces as shared facets;
 * optionally with Stalling et al.'s weights for smooth surfaces) to the request's size and
 * boundary-distance fields (Mesh_criteria_3 with facet size, facet distance and cell size fields),
 * then removes slivers (exude_mesh_3). Jamin, Alliez, Yvinec & Boissonnat, "CGALmesh: a generic
 * framework for Delaunay mesh generation", ACM TOMS 41(4), 2015. CGAL Mesh_3 is GPL-3.0: this
 * class lives in AdaptiveRT::Meshing, built only with ART_WITH_GPL_MESHING.
 */
#ifndef vtkCGALImageDomainMesher_h
#define vtkCGALImageDomainMesher_h

#include "AdaptiveRTMeshingModule.h"
#include "vtkImageDomainMesher.h"

class ADAPTIVERTMESHING_EXPORT vtkCGALImageDomainMesher : public vtkImageDomainMesher
{
public:
  static vtkCGALImageDomainMesher* New();
  vtkTypeMacro(vtkCGALImageDomainMesher, vtkImageDomainMesher);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  bool IsAvailable() const override { return true; }
  art::ImageDomainMesh Mesh(const art::ImageDomainRequest& request) override;

protected:
  vtkCGALImageDomainMesher() = default;
  ~vtkCGALImageDomainMesher() override = default;

private:
  vtkCGALImageDomainMesher(const vtkCGALImageDomainMesher&) = delete;
  void operator=(const vtkCGALImageDomainMesher&) = delete;
};

#endif
