// CellLists: the triangle lists of a structure's voxels in one array, each list preceded by its
// length. Record indices take 16 bits when the store holds at most 65,536 triangles (a list
// longer than 65,534 gives its length in three words), 32 bits otherwise.
#ifndef art_CellLists_h
#define art_CellLists_h

#include <cstdint>
#include <vector>

namespace art
{
class CellLists
{
public:
  explicit CellLists(size_t triangles = 0) : Narrow(triangles <= 65536) {}

  bool IsNarrow() const { return Narrow; }

  /// Appends a list; returns its offset (what Read takes).
  std::uint32_t Append(const std::uint32_t* ids, std::uint32_t n)
  {
    if (Narrow)
    {
      const std::uint32_t at = static_cast<std::uint32_t>(Ids16.size());
      if (n < 0xffffu)
      {
        Ids16.push_back(static_cast<std::uint16_t>(n));
      }
      else
      {
        Ids16.push_back(0xffffu);
        Ids16.push_back(static_cast<std::uint16_t>(n & 0xffffu));
        Ids16.push_back(static_cast<std::uint16_t>(n >> 16));
      }
      for (std::uint32_t k = 0; k < n; ++k)
      {
        Ids16.push_back(static_cast<std::uint16_t>(ids[k]));
      }
      return at;
    }
    const std::uint32_t at = static_cast<std::uint32_t>(Ids32.size());
    Ids32.push_back(n);
    Ids32.insert(Ids32.end(), ids, ids + n);
    return at;
  }

  /// The list at `offset` of the array `base` (Data16 or Data32).
  static const std::uint16_t* Read(const std::uint16_t* base, std::uint32_t offset, std::uint32_t& n)
  {
    const std::uint16_t* p = base + offset;
    if (p[0] != 0xffffu)
    {
      n = p[0];
      return p + 1;
    }
    n = std::uint32_t(p[1]) | std::uint32_t(p[2]) << 16;
    return p + 3;
  }
  static const std::uint32_t* Read(const std::uint32_t* base, std::uint32_t offset, std::uint32_t& n)
  {
    n = base[offset];
    return base + offset + 1;
  }

  /// Calls f(base) with the array of the width in use, so a walk is compiled for both.
  template <class F>
  void With(F&& f) const
  {
    if (Narrow)
    {
      f(Ids16.data());
    }
    else
    {
      f(Ids32.data());
    }
  }

  void ShrinkToFit()
  {
    Ids16.shrink_to_fit();
    Ids32.shrink_to_fit();
  }
  void Clear()
  {
    Ids16.clear();
    Ids32.clear();
  }
  /// Words stored (lengths included): what a budget on references counts.
  size_t Size() const { return Narrow ? Ids16.size() : Ids32.size(); }
  size_t MemoryBytes() const { return Ids16.size() * sizeof(std::uint16_t) + Ids32.size() * sizeof(std::uint32_t); }

private:
  bool Narrow = true;
  std::vector<std::uint16_t> Ids16;
  std::vector<std::uint32_t> Ids32;
};
} // namespace art

#endif
