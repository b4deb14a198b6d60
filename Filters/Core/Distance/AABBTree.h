// AABB tree over a triangle soup (Algorithm 1, line 1): a binary bounding-volume hierarchy whose
// splits minimise the surface-area heuristic. Split candidates follow Hunt, Mark & Stoll (2006)
// [4]: a few uniform samples first, then more samples placed where the primitive count changes
// fastest. Query: the closest point, with the feature it lies on. (The octree outline passes each
// node's triangles on to its children, so it needs no box query.)
#ifndef ShrinkWrap_AABBTree_h
#define ShrinkWrap_AABBTree_h

#include "Common/TriangleSoup.h"
#include "Distance/BoxHierarchy.h"
#include "Distance/TriangleDistance.h"

#include <array>
#include <limits>
#include <vector>

namespace shrinkwrap
{

struct AABBTreeSettings
{
  int leafSize = 4;               // at most this many triangles in a leaf
  int uniformSamples = 8;         // first pass of the split search, per axis
  int adaptiveSamples = 8;        // second pass, placed by primitive density
  int parallelSubtreeSize = 4096; // subtrees this small are built in parallel
};

struct ClosestHit
{
  int triangle = -1; // -1: nothing within the search radius
  double squaredDistance = std::numeric_limits<double>::infinity();
  Vec3 point = Vec3::Zero();
  Feature feature = Feature::Face;
};

class AABBTree
{
public:
  explicit AABBTree(const TriangleSoup& soup, const AABBTreeSettings& settings = {});

  // Nearest point of the soup to p, searched within sqrt(maxSquaredDistance).
  ClosestHit closestPoint(
    const Vec3& p, double maxSquaredDistance = std::numeric_limits<double>::infinity()) const;

  const Box& bounds() const { return this->Nodes.front().box; }

  // The hierarchy itself, for other queries over the same nodes (WindingNumber.h). Node 0 is the
  // root.
  using Node = HierarchyNode; // a leaf's slots index Order
  const HierarchyNodes& nodes() const { return this->Nodes; }
  int triangleAt(int slot) const { return this->Order[slot]; } // the soup's triangle in a leaf slot

private:
  struct Prim
  {
    Box box;
    Vec3 centroid;
    int id;
  };

  struct Subtree
  {
    int index, begin, end, depth;
  };
  struct SplitScratch;
  AABBTree() = default;
  void buildInParallel(LargeVector<Prim>& prims, const AABBTreeSettings& s);
  void build(HierarchyNodes& nodes, LargeVector<Prim>& prims, int index, int begin, int end,
    int depth, const AABBTreeSettings& s, SplitScratch& scratch, std::vector<Subtree>* deferred);
  int splitPosition(LargeVector<Prim>& prims, int begin, int end, const Box& centroids,
    const AABBTreeSettings& s, SplitScratch& scratch) const;

  // Megabytes for a large target: huge pages, whose first writes fault 2 MiB at a time.
  HierarchyNodes Nodes;
  LargeVector<int> Order;                   // soup triangle index per leaf slot
  LargeVector<std::array<Vec3, 3>> Corners; // triangle corners in leaf order, for locality
  struct Plane // n . x = offset, |n| = 1 (zero for a degenerate triangle: never skipped)
  {
    Vec3 normal = Vec3::Zero();
    double offset = 0;
  };
  LargeVector<Plane> Planes; // the triangles' planes in leaf order: a cheap bound first
};

} // namespace shrinkwrap

#endif
