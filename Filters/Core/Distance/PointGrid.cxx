#include "PointGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shrinkwrap
{

PointGrid::PointGrid(const std::vector<Vec3>& points, double cell)
  : Points(points)
  , Origin(Box::around(points).min)
  , Cell(cell)
{
  std::vector<std::pair<std::int64_t, int>> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    keyed[i] = { key(this->binOf(points[i])), static_cast<int>(i) };
  }
  std::sort(keyed.begin(), keyed.end());
  this->Order.resize(keyed.size());
  for (std::size_t s = 0; s < keyed.size(); ++s)
  {
    this->Order[s] = keyed[s].second;
    auto& range = this->Bins.try_emplace(keyed[s].first, static_cast<std::uint32_t>(s), 0).first->second;
    range.second = static_cast<std::uint32_t>(s + 1);
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

double PointGrid::neighbourDistance(int id, double radius) const
{
  double best = std::numeric_limits<double>::infinity();
  this->forEachWithin(this->Points[id], radius, [&](int other) {
    const double d = (this->Points[other] - this->Points[id]).squaredNorm();
    if (d > 0)
      best = std::min(best, d);
  });
  return std::sqrt(best);
}

} // namespace shrinkwrap
