// OriginalIndexMap: a non-decreasing map from a store's record to its input index (cell id), kept
// as runs where it steps by one (triangles, a few dropped) or stays (the triangles of one strip or
// polygon), or as a plain array when runs would not be smaller.
#ifndef art_OriginalIndexMap_h
#define art_OriginalIndexMap_h

#include <algorithm>
#include <cstdint>
#include <vector>

namespace art
{
class OriginalIndexMap
{
public:
  /// `original` must be non-decreasing.
  void Assign(const std::vector<long long>& original)
  {
    Runs.clear();
    Plain.clear();
    Wide.clear();
    for (size_t i = 0; i < original.size(); ++i)
    {
      if (!Runs.empty())
      {
        Run& r = Runs.back();
        const long long step = original[i] - original[i - 1];
        if (i - r.first == 1 && (step == 0 || step == 1))
        {
          r.step = static_cast<std::uint32_t>(step);
        }
        if (i - r.first >= 1 && step == r.step)
        {
          continue;
        }
      }
      Runs.push_back({ static_cast<std::uint32_t>(i), 1, original[i] });
    }
    if (Runs.size() * sizeof(Run) > original.size() * sizeof(std::uint32_t))
    {
      Runs.clear();
      const bool narrow = original.empty() || original.back() <= 0xffffffffLL;
      for (long long o : original)
      {
        if (narrow)
        {
          Plain.push_back(static_cast<std::uint32_t>(o));
        }
        else
        {
          Wide.push_back(o);
        }
      }
    }
  }

  long long At(size_t record) const
  {
    if (!Plain.empty())
    {
      return Plain[record];
    }
    if (!Wide.empty())
    {
      return Wide[record];
    }
    const auto it = std::upper_bound(Runs.begin(), Runs.end(), record,
                      [](size_t rec, const Run& r) { return rec < r.first; }) - 1;
    return it->base + static_cast<long long>(it->step) * static_cast<long long>(record - it->first);
  }

  size_t MemoryBytes() const
  {
    return Runs.size() * sizeof(Run) + Plain.size() * sizeof(std::uint32_t) + Wide.size() * sizeof(long long);
  }

private:
  struct Run
  {
    std::uint32_t first; ///< first record of the run
    std::uint32_t step;  ///< 0 or 1
    long long base;      ///< input index of the first record
  };
  std::vector<Run> Runs;
  std::vector<std::uint32_t> Plain;
  std::vector<long long> Wide;
};
} // namespace art

#endif
