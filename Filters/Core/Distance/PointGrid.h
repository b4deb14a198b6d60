// Points binned in a uniform hash grid, for the query the k-d tree (PointTree.h) does not answer:
// every point within a radius, the neighbourhood a local surface fit needs (PointSurface.h).
#ifndef ShrinkWrap_PointGrid_h
#define ShrinkWrap_PointGrid_h

#include "Common/Box.h"
#include "Common/HugePages.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace shrinkwrap
{

class PointGrid
{
public:
  // `cell` > 0: the bin size; radius queries are fastest with a cell about the radius.
  template <typename Points> // a std::vector<Vec3> or a PointList (PointTree.h)
  PointGrid(const Points& points, double cell)
    : PointGrid(points.data(), points.size(), Box::around(points).min, cell)
  {
  }

  // Calls f(index, point) for every point within `radius` of x.
  template <typename F>
  void forEachWithin(const Vec3& x, double radius, F&& f) const
  {
    this->forEachWithinBins(
      x, radius, [](const Bin&) { return true; }, std::forward<F>(f));
  }

  // The same points, but only from the bins that can hold points within `lineRadius` of the line
  // through `onLine` along unit `direction`, in the same order (the bins left out hold none).
  template <typename F>
  void forEachWithinNearLine(const Vec3& x, double radius, const Vec3& onLine,
    const Vec3& direction, double lineRadius, F&& f) const
  {
    // A bin's points lie within half its diagonal of its centre.
    const double reach = lineRadius + (0.5 * std::sqrt(3.0) + kSlack) * this->Cell;
    this->forEachWithinBins(
      x, radius,
      [&](const Bin& b) {
        const Vec3 off = this->centreOf(b) - onLine;
        const double along = off.dot(direction);
        return off.squaredNorm() - along * along <= reach * reach;
      },
      std::forward<F>(f));
  }

  // The point nearest x within `radius` (inclusive): false where none is. The bin of x first, then
  // only the bins nearer than the nearest found so far.
  bool nearest(const Vec3& x, double radius, int& index, Vec3& point, double& squaredDistance) const
  {
    double best = radius * radius;
    int found = -1;
    auto scan = [&](const Slot* bin) {
      for (std::uint32_t s = bin->begin; s < bin->end; ++s)
      {
        const double d2 = (this->Sorted[s] - x).squaredNorm();
        if (d2 < best || (found < 0 && d2 == best))
        {
          best = d2;
          found = static_cast<int>(s);
        }
      }
    };
    const Bin home = this->binOf(x);
    if (const Slot* bin = this->find(key(home)))
    {
      scan(bin);
    }
    const auto low = this->binOf(x - Vec3::Constant(radius));
    const auto high = this->binOf(x + Vec3::Constant(radius));
    for (std::int64_t k = low[2]; k <= high[2]; ++k)
      for (std::int64_t j = low[1]; j <= high[1]; ++j)
        for (std::int64_t i = low[0]; i <= high[0]; ++i)
        {
          // A bin no nearer than the best holds no point that would replace it (a tie keeps the
          // first found; with none found yet, a point at exactly the radius still counts).
          const Bin b{ i, j, k };
          const double d2 = this->squaredDistanceToBin(x, b);
          if (b == home || d2 > best || (found >= 0 && d2 == best))
            continue;
          if (const Slot* bin = this->find(key(b)))
            scan(bin);
        }
    if (found < 0)
      return false;
    index = this->Order[found];
    point = this->Sorted[found];
    squaredDistance = best;
    return true;
  }

private:
  PointGrid(const Vec3* points, std::size_t count, const Vec3& origin, double cell);

  using Bin = std::array<std::int64_t, 3>;
  template <typename Keep, typename F>
  void forEachWithinBins(const Vec3& x, double radius, Keep&& keep, F&& f) const
  {
    const auto low = this->binOf(x - Vec3::Constant(radius));
    const auto high = this->binOf(x + Vec3::Constant(radius));
    const double r2 = radius * radius;
    for (std::int64_t k = low[2]; k <= high[2]; ++k)
      for (std::int64_t j = low[1]; j <= high[1]; ++j)
        for (std::int64_t i = low[0]; i <= high[0]; ++i)
        {
          if (!keep(Bin{ i, j, k }))
            continue;
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
  Vec3 centreOf(const Bin& b) const
  {
    return this->Origin + this->Cell * Vec3(b[0] + 0.5, b[1] + 0.5, b[2] + 0.5);
  }
  // Bins widened by this many cells where points are told apart by them: a point binned by binOf's
  // rounding may lie a hair outside its bin's box.
  static constexpr double kSlack = 1e-9;
  double squaredDistanceToBin(const Vec3& x, const Bin& b) const
  {
    double d2 = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double lo = this->Origin[a] + this->Cell * (b[a] - kSlack),
                   hi = this->Origin[a] + this->Cell * (b[a] + 1 + kSlack);
      const double d = x[a] < lo ? lo - x[a] : (x[a] > hi ? x[a] - hi : 0.0);
      d2 += d * d;
    }
    return d2;
  }
  Bin binOf(const Vec3& p) const;
  static std::int64_t key(const Bin& b) // unique for bins within +-2^20 (binOf clamps to that)
  {
    const auto bits = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1FFFFF; };
    return static_cast<std::int64_t>((bits(b[0]) << 42) | (bits(b[1]) << 21) | bits(b[2]));
  }

  // The occupied bins in an open-addressing table (a lookup per bin of every query: no node
  // chasing).
  struct Slot
  {
    std::int64_t key = -1;            // -1: empty (keys are non-negative)
    std::uint32_t begin = 0, end = 0; // the bin's range in Order
  };
  std::size_t slotOf(std::int64_t k) const
  {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(k) * 0x9E3779B97F4A7C15ull) >> 32) &
      this->Mask;
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
  LargeVector<int> Order;   // point indices sorted by bin
  LargeVector<Vec3> Sorted; // the points in that order: a bin's lie side by side in memory
  std::vector<Slot> Bins;   // at most half full
  std::size_t Mask = 0;
};

} // namespace shrinkwrap

#endif
