// A k-d tree over points: the nearest point to a query, for a point set's distance
// (PointSource.h) and for its spacing, a point's nearest neighbour at another position. Splits at
// the median along the box's longest side, so that it is balanced and built in O(n log n); the
// points are kept in leaf order for locality. Points with a NaN or infinite coordinate are left
// out.
#ifndef ShrinkWrap_PointTree_h
#define ShrinkWrap_PointTree_h

#include "Common/HugePages.h"
#include "Distance/BoxHierarchy.h"

#include <limits>
#include <vector>

namespace shrinkwrap
{

// A cloud's points: megabytes at a scan's size, so in huge pages where they are first written.
using PointList = LargeVector<Vec3>;

class PointTree
{
public:
  // Leaves of up to 32 points: against 8, a third less to build and a sixth less per query on
  // 200,000 noisy points (fewer nodes to test and to fault in; a leaf's points are read in one run
  // of memory).
  template <typename Points> // a std::vector<Vec3> or a PointList
  explicit PointTree(const Points& points, int leafSize = 32)
    : PointTree(points.data(), points.size(), leafSize)
  {
  }

  struct Entry // a point with its input index: split together while building, then kept in leaf
               // order
  {
    Vec3 point;
    int id;
  };

  struct Hit
  {
    int id = -1; // the input point's index; -1: none within the search radius
    double squaredDistance = std::numeric_limits<double>::infinity();
  };
  // The nearest point to x within sqrt(maxSquaredDistance); with `apart`, the nearest at another
  // position than x's (a point's neighbour, its duplicates left out).
  Hit nearest(const Vec3& x, double maxSquaredDistance = std::numeric_limits<double>::infinity(),
    bool apart = false) const;

private:
  PointTree(const Vec3* points, std::size_t count, int leafSize);

  HierarchyNodes Nodes;
  LargeVector<Entry> Sorted; // built in place: no copy (fresh memory costs as much as the build)
};

} // namespace shrinkwrap

#endif
