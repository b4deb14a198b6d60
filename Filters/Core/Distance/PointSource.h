// A point set as a distance source (DistanceSource.h), for scans and sampled points (issue #13): the
// distance to the nearest input point, unsigned (points have no sides), from a k-d tree (PointTree.h)
// where a mesh has its AABB tree, so that band, sweeps and field come unchanged from Algorithm 1.
#ifndef ShrinkWrap_PointSource_h
#define ShrinkWrap_PointSource_h

#include "DistanceSource.h"
#include "PointTree.h"

#include <vector>

namespace shrinkwrap
{

class PointSource : public DistanceSource
{
public:
  explicit PointSource(PointList points); // taken over where moved in: no copy
  explicit PointSource(const std::vector<Vec3>& points); // copied (a soup's points, a test's)
  Box bounds() const override { return this->Bounds; }
  // The cells that hold a point (Algorithm 2's outline reduces to that).
  bool outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const override;
  // The nearest input point; side 0 and not sure: a point has no inside.
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  const PointList& points() const { return this->Points; }
  // See medianNeighbourDistance below (from this source's tree).
  double medianNeighbourDistance() const;

private:
  PointList Points;
  Box Bounds;
  PointTree Tree;
};

// The median distance from a point to its nearest neighbour at another position (over up to 20,000
// of the points); 0 when the points have no such neighbours (all coincide).
double medianNeighbourDistance(const std::vector<Vec3>& points);

} // namespace shrinkwrap

#endif
