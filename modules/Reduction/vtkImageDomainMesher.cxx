#include "vtkImageDomainMesher.h"

#include "Error.h"

#include <vtkObjectFactory.h>

vtkObjectFactoryNewMacro(vtkImageDomainMesher);

void vtkImageDomainMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsAvailable: " << (this->IsAvailable() ? "yes" : "no") << "\n";
}

art::ImageDomainMesh vtkImageDomainMesher::Mesh(const art::ImageDomainRequest&)
{
  throw art::Error("regions and label maps are meshed by CGAL's Mesh_3 (AdaptiveRT::Meshing), which is not in "
                   "this build (configure with ART_WITH_GPL_MESHING=ON and libcgal-dev, libtet1.5-dev installed)");
}
