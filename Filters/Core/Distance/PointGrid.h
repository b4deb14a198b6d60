// Points binned in a uniform hash grid, for the queries the AABB tree does not answer: every point
// within a radius (the neighbourhood a local surface fit needs, PointSurface.h) and the nearest
// neighbour of a point among the others (the sampling's spacing).
#ifndef ShrinkWrap_PointGrid_h
#define ShrinkWrap_PointGrid_h

#include "Box.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace shrinkwrap
{

class PointGrid
{
public:
  // `cell` > 0: the bin size; radius queries are fastest with a cell about the radius.
  PointGrid(const std::vector<Vec3>& points, double cell);

  // Calls f(index) for every point within `radius` of x.
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
          const auto range = this->Bins.find(key({ i, j, k }));
          if (range == this->Bins.end())
            continue;
          for (std::uint32_t s = range->second.first; s < range->second.second; ++s)
          {
            const int id = this->Order[s];
            if ((this->Points[id] - x).squaredNorm() <= r2)
              f(id);
          }
        }
  }
  // The distance from point `id` to its nearest point within `radius` apart from the points at its
  // position (duplicates say nothing of the spacing); infinity: none.
  double neighbourDistance(int id, double radius) const;

private:
  using Bin = std::array<std::int64_t, 3>;
  Bin binOf(const Vec3& p) const;
  static std::int64_t key(const Bin& b) // unique for bins within +-2^20 (binOf clamps to that)
  {
    const auto bits = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1FFFFF; };
    return static_cast<std::int64_t>((bits(b[0]) << 42) | (bits(b[1]) << 21) | bits(b[2]));
  }

  const std::vector<Vec3>& Points;
  Vec3 Origin;
  double Cell;
  std::vector<int> Order; // point indices sorted by bin
  std::unordered_map<std::int64_t, std::pair<std::uint32_t, std::uint32_t>> Bins; // bin -> range in Order
};

} // namespace shrinkwrap

#endif
