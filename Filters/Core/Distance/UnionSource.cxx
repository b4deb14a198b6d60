#include "Distance/UnionSource.h"

#include <algorithm>
#include <utility>

namespace shrinkwrap
{

UnionSource::UnionSource(std::vector<std::shared_ptr<const DistanceSource>> parts)
  : Parts(std::move(parts))
{
}

Box UnionSource::bounds() const
{
  Box box;
  for (const auto& part : this->Parts)
  {
    box.extend(part->bounds());
  }
  return box;
}

bool UnionSource::outline(
  const GridLattice& lattice, const Progress& progress, IndexList& cells) const
{
  cells.clear();
  IndexList own;
  const double share = 1.0 / std::max<std::size_t>(this->Parts.size(), 1);
  for (std::size_t i = 0; i < this->Parts.size(); ++i)
  {
    if (!this->Parts[i]->outline(lattice, progress.stage(i * share, (i + 1) * share), own))
    {
      return false;
    }
    cells.insert(cells.end(), own.begin(), own.end());
  }
  // A cell two parts touch is one cell of the outline.
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return true;
}

SourcePoint UnionSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  SourcePoint best;
  for (const auto& part : this->Parts)
  {
    // Each part searches only within the nearest distance found so far.
    const SourcePoint p = part->closestPoint(x, std::min(maxSquaredDistance, best.squaredDistance));
    if (p.found && p.squaredDistance < best.squaredDistance)
    {
      best = p;
    }
  }
  best.side = 0;
  best.sure = false;
  return best;
}

std::vector<std::array<Vec3, 2>> UnionSource::rims(double creaseAngle) const
{
  std::vector<std::array<Vec3, 2>> rims;
  for (const auto& part : this->Parts)
  {
    const auto own = part->rims(creaseAngle);
    rims.insert(rims.end(), own.begin(), own.end());
  }
  return rims;
}

const TriangleSoup* UnionSource::triangles() const
{
  for (const auto& part : this->Parts)
  {
    if (const TriangleSoup* soup = part->triangles())
    {
      return soup;
    }
  }
  return nullptr;
}

} // namespace shrinkwrap
