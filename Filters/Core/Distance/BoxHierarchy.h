// What the two bounding-box hierarchies share (AABBTree.h over triangles, PointTree.h over points):
// nodes holding a box, inner nodes with their two children side by side, leaves a range of slots;
// and the nearest-first search over them that both closest-point queries are.
#ifndef ShrinkWrap_BoxHierarchy_h
#define ShrinkWrap_BoxHierarchy_h

#include "Common/Box.h"
#include "Common/HugePages.h"

#include <vector>

namespace shrinkwrap
{

struct HierarchyNode
{
  Box box;
  int first; // leaf: first slot; inner: index of the left child (right = first + 1)
  int count; // leaf: number of slots; inner: 0
};

// A hierarchy's nodes, root first (a large target's tree is megabytes: huge pages).
using HierarchyNodes = LargeVector<HierarchyNode>;

// Deeper trees are not built (a leaf then holds more slots).
constexpr int kMaxHierarchyDepth = 64;

// Calls visit(slot) for the slots of the leaves whose boxes lie nearer to p than `best` (a squared
// distance that visit lowers as it finds nearer elements), nearer boxes first so that they prune
// more.
template <typename Visit>
void searchNearest(const HierarchyNodes& nodes, const Vec3& p, const double& best, Visit&& visit)
{
  if (nodes.empty())
  {
    return;
  }
  // Nodes wait with their boxes' distances, computed once, when their parent was opened.
  struct Pending
  {
    int node;
    double squaredDistance;
  };
  Pending stack[2 * kMaxHierarchyDepth + 2];
  int top = 0;
  stack[top++] = { 0, nodes.front().box.squaredDistance(p) };
  while (top > 0)
  {
    const Pending pending = stack[--top];
    if (pending.squaredDistance >= best)
    {
      continue;
    }
    const HierarchyNode& node = nodes[pending.node];
    if (node.count > 0)
    {
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        visit(k);
      }
      continue;
    }
    // Push the farther child first so that the nearer one is searched first.
    const int l = node.first, r = node.first + 1;
    const double dl = nodes[l].box.squaredDistance(p), dr = nodes[r].box.squaredDistance(p);
    if (dl <= dr)
    {
      stack[top++] = { r, dr };
      stack[top++] = { l, dl };
    }
    else
    {
      stack[top++] = { l, dl };
      stack[top++] = { r, dr };
    }
  }
}

} // namespace shrinkwrap

#endif
