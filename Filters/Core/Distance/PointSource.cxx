#include "PointSource.h"

#include "Parallel.h"
#include "PointGrid.h"

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
  const std::size_t n = points.size();
  const Vec3 size = Box::around(points).size();
  if (n < 2 || !(size.maxCoeff() > 0))
  {
    return 0;
  }
  // Bins of about one point each if the points filled the box; a surface's points are sparser there.
  const Vec3 sides = size.cwiseMax(1e-3 * size.maxCoeff());
  const double cell = std::cbrt(sides.prod() / static_cast<double>(n));
  const std::size_t stride = std::max<std::size_t>(1, n / 20000);
  // Points with no neighbour within the radius count as infinitely far, so the median is exact once
  // it is finite: flat or thin clouds (sparser than the box suggests) need a wider radius.
  for (double radius = cell; radius <= 64 * cell; radius *= 4)
  {
    const PointGrid grid(points, radius);
    std::vector<double> nearest((n + stride - 1) / stride);
    parallelFor(0, static_cast<vtkIdType>(nearest.size()), [&](vtkIdType b, vtkIdType e) {
      for (vtkIdType k = b; k < e; ++k)
      {
        nearest[k] = grid.neighbourDistance(static_cast<int>(k * stride), radius);
      }
    });
    std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
    if (const double median = nearest[nearest.size() / 2]; median < std::numeric_limits<double>::infinity())
    {
      return median;
    }
  }
  return 0;
}

SourcePoint PointSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  SourcePoint p = nearestOf(this->Tree.closestPoint(x, maxSquaredDistance));
  p.sure = false; // a point has no sides
  return p;
}

} // namespace shrinkwrap
