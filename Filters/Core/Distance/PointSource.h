// A point set as a distance source (DistanceSource.h), for scans and sampled points: the
// distance to the nearest input point, unsigned (points have no sides), from a k-d tree
// (PointTree.h) where a mesh has its AABB tree, so that band, sweeps and field come unchanged from
// Algorithm 1.
#ifndef ShrinkWrap_PointSource_h
#define ShrinkWrap_PointSource_h

#include "Distance/DistanceSource.h"
#include "Distance/PointTree.h"

#include <vector>

namespace shrinkwrap
{

// How far apart a point set's points lie, over up to 20,000 of them (0 and 0 when all coincide):
// `median`, the median distance from a point to its nearest neighbour at another position; and
// `sparse`, as much or more: that spacing where the points are sparsest (a scan's far side; strays,
// such as its outliers, aside), from the 99th percentile of its local mean, so that a gap sized by
// it spans the sampling's holes there too.
struct PointSpacing
{
  double median = 0;
  double sparse = 0;
};

class PointSource : public DistanceSource
{
public:
  explicit PointSource(PointList points);                // taken over where moved in: no copy
  explicit PointSource(const std::vector<Vec3>& points); // copied (a soup's points, a test's)
  Box bounds() const override { return this->Bounds; }
  // The cells that hold a point (Algorithm 2's outline reduces to that).
  bool outline(
    const GridLattice& lattice, const Progress& progress, IndexList& cells) const override;
  // The nearest input point; side 0 and not sure: a point has no inside.
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  const PointList& points() const { return this->Points; }
  // How far apart the points lie, from this source's tree (PointSpacing above).
  PointSpacing spacing() const;

private:
  PointList Points;
  Box Bounds;
  PointTree Tree;
};

// PointSpacing's median, for a list of points.
double medianNeighbourDistance(const std::vector<Vec3>& points);

} // namespace shrinkwrap

#endif
