#include "PointSource.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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

SourcePoint PointSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  const ClosestHit hit = this->Tree.closestPoint(x, maxSquaredDistance);
  SourcePoint p;
  if (hit.triangle < 0)
  {
    return p;
  }
  p.found = true;
  p.squaredDistance = hit.squaredDistance;
  p.point = hit.point;
  p.element = hit.triangle;
  p.sure = false;
  return p;
}

} // namespace shrinkwrap
