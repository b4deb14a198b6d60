#include "DistanceSource.h"

#include "Outline.h"

namespace shrinkwrap
{

TriangleSource::TriangleSource(const TriangleSoup& soup)
  : Soup(weldDuplicatePoints(soup))
  , Tree(this->Soup)
  , Normals(this->Soup)
{
}

bool TriangleSource::outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const
{
  return outlineCells(this->Soup, lattice, progress, cells);
}

SourcePoint TriangleSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
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
  p.side = (x - hit.point).dot(this->Normals.at(hit.triangle, hit.feature));
  return p;
}

} // namespace shrinkwrap
