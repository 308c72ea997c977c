// BruteForce: every triangle tested for every ray. The reference every accelerator is checked
// against (and the floor of the paper's tables).
#ifndef art_BruteForce_h
#define art_BruteForce_h

#include "AcceleratorQueries.h"

#include <numeric>

namespace art
{
class ADAPTIVERTTRIANGLEGRID_EXPORT BruteForce : public WalkingAccelerator<BruteForce>
{
public:
  explicit BruteForce(std::shared_ptr<const TriangleStore> s)
    : WalkingAccelerator<BruteForce>(std::move(s))
    , Ids(PlaneOrder(*S))
  {
  }
  size_t MemoryBytes() const override { return Ids.size() * sizeof(std::uint32_t); }
  std::string Name() const override { return "brute force"; }

  template <class Visitor>
  void Walk(const RayPrep&, double, double, Visitor& visit, Counters& c) const
  {
    ++c.voxelsVisited;
    visit(Ids.data(), static_cast<std::uint32_t>(Ids.size()), std::numeric_limits<double>::infinity());
  }

  template <class Visitor>
  void Near(const Vec3&, const double&, Visitor& visit, Counters& c) const
  {
    ++c.voxelsVisited;
    visit(Ids.data(), static_cast<std::uint32_t>(Ids.size()));
  }

  template <class Visitor>
  void Overlap(const Box3&, Visitor& visit) const
  {
    visit(Ids.data(), static_cast<std::uint32_t>(Ids.size()));
  }

private:
  std::vector<std::uint32_t> Ids;
};
} // namespace art

#endif
