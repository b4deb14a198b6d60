// Points binned in a uniform hash grid, for the query the k-d tree (PointTree.h) does not answer:
// every point within a radius, the neighbourhood a local surface fit needs (PointSurface.h).
#ifndef ShrinkWrap_PointGrid_h
#define ShrinkWrap_PointGrid_h

#include "Box.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace shrinkwrap
{

class PointGrid
{
public:
  // `cell` > 0: the bin size; radius queries are fastest with a cell about the radius.
  PointGrid(const std::vector<Vec3>& points, double cell);

  // Calls f(index, point) for every point within `radius` of x.
  template <typename F>
  void forEachWithin(const Vec3& x, double radius, F&& f) const
  {
    const auto low = this->binOf(x - Vec3::Constant(radius));
    const auto high = this->binOf(x + Vec3::Constant(radius));
    const double r2 = radius * radius;
    for (std::int64_t k = low[2]; k <= high[2]; ++k)
      for (std::int64_t j = low[1]; j <= high[1]; ++j)
        for (std::int64_t i = low[0]; i <= high[0]; ++i)
        {
          const Slot* bin = this->find(key({ i, j, k }));
          if (!bin)
            continue;
          for (std::uint32_t s = bin->begin; s < bin->end; ++s)
          {
            if ((this->Sorted[s] - x).squaredNorm() <= r2)
              f(this->Order[s], this->Sorted[s]);
          }
        }
  }

private:
  using Bin = std::array<std::int64_t, 3>;
  Bin binOf(const Vec3& p) const;
  static std::int64_t key(const Bin& b) // unique for bins within +-2^20 (binOf clamps to that)
  {
    const auto bits = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1FFFFF; };
    return static_cast<std::int64_t>((bits(b[0]) << 42) | (bits(b[1]) << 21) | bits(b[2]));
  }

  // The occupied bins in an open-addressing table (a lookup per bin of every query: no node chasing).
  struct Slot
  {
    std::int64_t key = -1; // -1: empty (keys are non-negative)
    std::uint32_t begin = 0, end = 0; // the bin's range in Order
  };
  std::size_t slotOf(std::int64_t k) const
  {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(k) * 0x9E3779B97F4A7C15ull) >> 32) & this->Mask;
  }
  const Slot* find(std::int64_t k) const
  {
    for (std::size_t s = this->slotOf(k);; s = (s + 1) & this->Mask)
    {
      if (this->Bins[s].key == k)
        return &this->Bins[s];
      if (this->Bins[s].key < 0)
        return nullptr;
    }
  }

  Vec3 Origin;
  double Cell;
  std::vector<int> Order;   // point indices sorted by bin
  std::vector<Vec3> Sorted; // the points in that order: a bin's lie side by side in memory
  std::vector<Slot> Bins; // at most half full
  std::size_t Mask = 0;
};

} // namespace shrinkwrap

#endif
