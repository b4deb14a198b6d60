#include "PointSource.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace shrinkwrap
{

namespace
{
TriangleSoup pointTriangles(const std::vector<Vec3>& points)
{
  TriangleSoup soup;
  soup.points = points;
  soup.triangles.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const int id = static_cast<int>(i);
    soup.triangles[i] = { id, id, id };
  }
  return soup;
}
} // namespace

PointSource::PointSource(const std::vector<Vec3>& points)
  : Points(pointTriangles(points))
  , Tree(this->Points)
{
}

bool PointSource::outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const
{
  cells.clear();
  cells.reserve(this->Points.points.size());
  for (const Vec3& p : this->Points.points)
  {
    std::array<int, 3> c;
    bool inside = true;
    for (int a = 0; a < 3; ++a)
    {
      const double u = std::floor((p[a] - lattice.origin[a]) / lattice.spacing[a]);
      inside = inside && u >= 0 && u <= lattice.dims[a] - 1; // a point on the far face: its last cell
      c[a] = static_cast<int>(std::clamp(u, 0.0, static_cast<double>(std::max(lattice.dims[a] - 2, 0))));
    }
    if (inside)
    {
      cells.push_back(lattice.index(c[0], c[1], c[2]));
    }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return progress.report(1);
}

double medianNeighbourDistance(const std::vector<Vec3>& points)
{
  const Box box = Box::around(points);
  const std::size_t n = points.size();
  const Vec3 size = box.size();
  if (n < 2 || !(size.maxCoeff() > 0))
  {
    return 0;
  }
  // Cells of about one point each if the points filled the box; a surface's points are sparser there.
  const Vec3 sides = size.cwiseMax(1e-3 * size.maxCoeff());
  const double cell = std::cbrt(sides.prod() / static_cast<double>(n));
  const auto cellOf = [&](const Vec3& p) {
    std::array<std::int64_t, 3> c;
    for (int a = 0; a < 3; ++a)
    {
      c[a] = static_cast<std::int64_t>(std::floor((p[a] - box.min[a]) / cell));
    }
    return c;
  };
  const auto key = [](const std::array<std::int64_t, 3>& c) { return (c[0] << 42) ^ (c[1] << 21) ^ c[2]; };
  std::vector<std::pair<std::int64_t, int>> order(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    order[i] = { key(cellOf(points[i])), static_cast<int>(i) };
  }
  std::sort(order.begin(), order.end());
  std::vector<double> nearest;
  const std::size_t stride = std::max<std::size_t>(1, n / 20000);
  for (std::size_t i = 0; i < n; i += stride)
  {
    const auto c = cellOf(points[i]);
    double best = std::numeric_limits<double>::infinity();
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
          const std::int64_t k = key({ c[0] + dx, c[1] + dy, c[2] + dz });
          auto it = std::lower_bound(order.begin(), order.end(), std::make_pair(k, -1));
          for (; it != order.end() && it->first == k; ++it)
          {
            if (it->second != static_cast<int>(i))
            {
              best = std::min(best, (points[it->second] - points[i]).squaredNorm());
            }
          }
        }
    if (best < std::numeric_limits<double>::infinity())
    {
      nearest.push_back(std::sqrt(best));
    }
  }
  if (nearest.empty())
  {
    return 0;
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

SourcePoint PointSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  SourcePoint p = nearestOf(this->Tree.closestPoint(x, maxSquaredDistance));
  p.sure = false; // a point has no sides
  return p;
}

} // namespace shrinkwrap
