#include "rendering/ReducedTets.h"

#if defined(ART_HAVE_Reduction) && defined(ART_HAVE_TetRayCast)
namespace cli
{
art::TetMesh ToTetMesh(const art::ReducedMesh& r)
{
  std::vector<art::Vec3> p(r.NumberOfVertices());
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    p[i] = art::Vec3(&r.Points[3 * i]);
  }
  std::vector<std::array<int, 4>> t(r.NumberOfTets());
  for (std::size_t i = 0; i < t.size(); ++i)
  {
    t[i] = { r.Tets[4 * i], r.Tets[4 * i + 1], r.Tets[4 * i + 2], r.Tets[4 * i + 3] };
  }
  return art::TetMesh(std::move(p), r.Values, std::move(t));
}
} // namespace cli
#endif
