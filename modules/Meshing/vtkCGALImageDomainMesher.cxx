// The one translation unit that includes CGAL's Mesh_3 (slow to compile: keep it the only one).
#include "vtkCGALImageDomainMesher.h"

#include "Error.h"

#include <vtkObjectFactory.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>

#include <chrono>
#include <cstring>
#include <unordered_map>

vtkStandardNewMacro(vtkCGALImageDomainMesher);

namespace
{
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Domain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;
namespace params = CGAL::parameters;

// A request's SizeGrid as a Mesh_3 sizing field, never below `floor`.
struct Field
{
  typedef K::FT FT;
  typedef K::Point_3 Point_3;
  typedef Domain::Index Index;
  const art::SizeGrid* grid;
  double floor;
  FT operator()(const Point_3& p, const int, const Index&) const
  {
    const double q[3] = { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) };
    return std::max(floor, grid->At(q));
  }
};

// Subdomain 1 where the interpolated value lies in [lo, hi], 0 elsewhere.
struct InRange
{
  double lo, hi;
  int operator()(double v) const { return v >= lo && v <= hi ? 1 : 0; }
};

// An Image_3 owning a copy of `data` (n words of `bytes` each, of CGAL's word kind and sign).
CGAL::Image_3 MakeImage(const art::ImageDomainRequest& r, const void* data, int bytes, WORD_KIND kind, SIGN sign)
{
  _image* im = _createImage(r.Dims[0], r.Dims[1], r.Dims[2], 1, r.Spacing[0], r.Spacing[1], r.Spacing[2], bytes,
    kind, sign);
  if (!im)
  {
    throw art::Error("could not allocate the image CGAL meshes");
  }
  const size_t n = size_t(r.Dims[0]) * r.Dims[1] * r.Dims[2];
  std::memcpy(im->data, data, n * bytes);
  return CGAL::Image_3(im);
}

Domain MakeDomain(const art::ImageDomainRequest& r, std::vector<CGAL::Image_3>& keep)
{
  if (r.Values)
  {
    keep.push_back(MakeImage(r, r.Values, 4, WK_FLOAT, SGN_SIGNED));
    // Outside the box the value is far below the range: the surface closes on the last voxels.
    const double outside = r.Lo - 1e6 * (1.0 + std::fabs(r.Hi - r.Lo) + std::fabs(r.Lo));
    return Domain::create_gray_image_mesh_domain(keep[0], params::iso_value = 0.5,
      params::image_values_to_subdomain_indices = InRange{ r.Lo, r.Hi }, params::value_outside = outside,
      params::relative_error_bound = r.RelativeError);
  }
  keep.push_back(MakeImage(r, r.Slots, 4, WK_FIXED, SGN_SIGNED));
  if (r.Weights)
  {
    keep.push_back(MakeImage(r, r.Weights, 1, WK_FIXED, SGN_UNSIGNED));
    return Domain::create_labeled_image_mesh_domain(keep[0], params::weights = keep[1],
      params::relative_error_bound = r.RelativeError);
  }
  return Domain::create_labeled_image_mesh_domain(keep[0], params::relative_error_bound = r.RelativeError);
}

art::ImageDomainMesh Extract(const C3t3& c3t3)
{
  art::ImageDomainMesh out;
  std::unordered_map<Tr::Vertex_handle, int> index;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    int ids[4];
    for (int i = 0; i < 4; ++i)
    {
      const Tr::Vertex_handle v = c->vertex(i);
      auto it = index.find(v);
      if (it == index.end())
      {
        it = index.emplace(v, static_cast<int>(index.size())).first;
        const auto& p = v->point();
        out.Points.push_back(CGAL::to_double(p.x()));
        out.Points.push_back(CGAL::to_double(p.y()));
        out.Points.push_back(CGAL::to_double(p.z()));
      }
      ids[i] = it->second;
    }
    out.Tets.insert(out.Tets.end(), ids, ids + 4);
    out.Subdomain.push_back(static_cast<int>(c3t3.subdomain_index(c)));
  }
  return out;
}
} // namespace

void vtkCGALImageDomainMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CGAL " << CGAL_VERSION_STR << "\n";
}

art::ImageDomainMesh vtkCGALImageDomainMesher::Mesh(const art::ImageDomainRequest& r)
{
  if (!r.Values == !r.Slots || r.Dims[0] < 2 || r.Dims[1] < 2 || r.Dims[2] < 2)
  {
    throw art::Error("internal: an image domain needs either values or labels, and 2 voxels along each axis");
  }
  const auto t0 = std::chrono::steady_clock::now();
  const double smallest = 1e-3 * std::min({ r.Spacing[0], r.Spacing[1], r.Spacing[2] });
  try
  {
    std::vector<CGAL::Image_3> images;
    images.reserve(2);
    const Domain domain = MakeDomain(r, images);
    const Field size{ &r.Size, smallest }, distance{ &r.Distance, smallest };
    const Criteria criteria(params::facet_angle = r.FacetAngle, params::facet_size = size,
      params::facet_distance = distance, params::cell_radius_edge_ratio = r.RadiusEdge, params::cell_size = size);
    C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
    if (r.Exude)
    {
      CGAL::exude_mesh_3(c3t3, params::time_limit = 0);
    }
    art::ImageDomainMesh out = Extract(c3t3);
    out.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }
  catch (const art::Error&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    throw art::Error(std::string("CGAL's Mesh_3 failed: ") + e.what());
  }
}
