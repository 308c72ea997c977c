// OriginalIndexMap: a non-decreasing map from a store's record to its input index (cell id), kept
// as runs where it steps by one (triangles, a few dropped) or stays (the triangles of one strip or
// polygon), or as a plain array when runs would not be smaller. A lookup starts from the run
// that holds the block of 64 records around it, so it scans a few runs at most.
#ifndef art_OriginalIndexMap_h
#define art_OriginalIndexMap_h

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
    Start.clear();
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
    Start.clear();
    if (Runs.size() * sizeof(Run) + (Runs.size() > 8 ? original.size() / 64 + 1 : 0) * sizeof(std::uint32_t) >
      original.size() * sizeof(std::uint32_t))
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
      return;
    }
    // Start[b]: the last run that begins at or before record 64 b (a few runs are just scanned).
    std::uint32_t r = 0;
    for (size_t b = 0; Runs.size() > 8 && b * 64 < original.size(); ++b)
    {
      while (r + 1 < Runs.size() && Runs[r + 1].first <= b * 64)
      {
        ++r;
      }
      Start.push_back(r);
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
    size_t r = Start.empty() ? 0 : Start[record / 64];
    while (r + 1 < Runs.size() && Runs[r + 1].first <= record)
    {
      ++r;
    }
    const Run& run = Runs[r];
    return run.base + static_cast<long long>(run.step) * static_cast<long long>(record - run.first);
  }

  size_t MemoryBytes() const
  {
    return Runs.size() * sizeof(Run) + Start.size() * sizeof(std::uint32_t) + Plain.size() * sizeof(std::uint32_t) + Wide.size() * sizeof(long long);
  }

private:
  struct Run
  {
    std::uint32_t first; ///< first record of the run
    std::uint32_t step;  ///< 0 or 1
    long long base;      ///< input index of the first record
  };
  std::vector<Run> Runs;
  std::vector<std::uint32_t> Start; ///< per 64 records: the run holding the first of them
  std::vector<std::uint32_t> Plain;
  std::vector<long long> Wide;
};
} // namespace art

#endif
