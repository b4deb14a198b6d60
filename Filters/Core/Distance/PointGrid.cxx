#include "Distance/PointGrid.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

PointGrid::PointGrid(const Vec3* points, std::size_t count, const Vec3& origin, double cell)
  : Origin(origin)
  , Cell(cell)
{
  LargeVector<std::pair<std::int64_t, int>> keyed(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    keyed[i] = { key(this->binOf(points[i])), static_cast<int>(i) };
  }
  std::sort(keyed.begin(), keyed.end());
  // Sized for the occupied bins, not the points: a fit's bins hold dozens (at 200,000 points a
  // table per point was 8 MB to zero).
  std::size_t bins = 0;
  for (std::size_t s = 0; s < keyed.size(); ++s)
  {
    bins += s == 0 || keyed[s].first != keyed[s - 1].first;
  }
  std::size_t size = 2;
  while (size < 2 * bins)
  {
    size <<= 1;
  }
  this->Bins.assign(size, Slot());
  this->Mask = size - 1;
  this->Order.resize(keyed.size());
  this->Sorted.resize(keyed.size());
  std::size_t last = 0; // the slot of the bin being filled
  for (std::size_t s = 0; s < keyed.size(); ++s)
  {
    this->Order[s] = keyed[s].second;
    this->Sorted[s] = points[keyed[s].second];
    if (s == 0 || keyed[s].first != keyed[s - 1].first)
    {
      std::size_t slot = this->slotOf(keyed[s].first);
      while (this->Bins[slot].key >= 0)
      {
        slot = (slot + 1) & this->Mask;
      }
      this->Bins[slot] = { keyed[s].first, static_cast<std::uint32_t>(s),
        static_cast<std::uint32_t>(s) };
      last = slot;
    }
    this->Bins[last].end = static_cast<std::uint32_t>(s + 1);
  }
}

PointGrid::Bin PointGrid::binOf(const Vec3& p) const
{
  Bin b;
  for (int a = 0; a < 3; ++a)
  {
    // Clamped so that far queries stay in the key's 21 bits.
    const double u = std::floor((p[a] - this->Origin[a]) / this->Cell);
    b[a] = static_cast<std::int64_t>(std::clamp(u, -1.0e6, 1.0e6));
  }
  return b;
}

} // namespace shrinkwrap
