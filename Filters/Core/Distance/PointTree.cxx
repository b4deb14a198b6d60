#include "Distance/PointTree.h"

#include "Common/Parallel.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

namespace
{
using Entry = PointTree::Entry;

Box boxOf(const LargeVector<Entry>& entries, int begin, int end)
{
  Box box;
  for (int k = begin; k < end; ++k)
  {
    box.extend(entries[k].point);
  }
  return box;
}

// Splits entries [begin, end) at their median along the longest side of their box; the middle.
int splitAtMedian(LargeVector<Entry>& entries, int begin, int end, const Box& box)
{
  int axis = 0;
  box.size().maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(entries.begin() + begin, entries.begin() + middle, entries.begin() + end,
    [axis](const Entry& a, const Entry& b) { return a.point[axis] < b.point[axis]; });
  return middle;
}

// The subtree over entries [begin, end) as nodes appended to `nodes`, its root first.
void buildSubtree(
  LargeVector<Entry>& entries, int begin, int end, int depth, int leafSize, HierarchyNodes& nodes)
{
  struct Range
  {
    int node, begin, end, depth;
  };
  std::vector<Range> pending{ { static_cast<int>(nodes.size()), begin, end, depth } };
  nodes.push_back({});
  while (!pending.empty())
  {
    const Range r = pending.back();
    pending.pop_back();
    const Box box = boxOf(entries, r.begin, r.end);
    nodes[r.node].box = box;
    if (r.end - r.begin <= leafSize || r.depth + 1 >= kMaxHierarchyDepth)
    {
      nodes[r.node].first = r.begin;
      nodes[r.node].count = r.end - r.begin;
      continue;
    }
    const int middle = splitAtMedian(entries, r.begin, r.end, box);
    const int left = static_cast<int>(nodes.size());
    nodes[r.node].first = left;
    nodes[r.node].count = 0;
    nodes.resize(nodes.size() + 2);
    pending.push_back({ left, r.begin, middle, r.depth + 1 });
    pending.push_back({ left + 1, middle, r.end, r.depth + 1 });
  }
}
} // namespace

PointTree::PointTree(const Vec3* points, std::size_t count, int leafSize)
{
  LargeVector<Entry>& entries = this->Sorted;
  entries.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    if (points[i].allFinite())
    {
      entries.push_back({ points[i], static_cast<int>(i) });
    }
  }
  if (entries.empty())
  {
    return;
  }
  leafSize = std::max(leafSize, 1);
  // The root's split, then its two halves built side by side (the build is a tenth of a wrap's time
  // at 200,000 points): each into nodes of its own, appended after the root's children.
  const int n = static_cast<int>(entries.size());
  if (n <= 4 * leafSize)
  {
    buildSubtree(entries, 0, n, 0, leafSize, this->Nodes);
  }
  else
  {
    const Box box = boxOf(entries, 0, n);
    const int middle = splitAtMedian(entries, 0, n, box);
    HierarchyNodes halves[2];
    parallelFor(0, 2, 1, [&](Index b, Index e) {
      for (Index h = b; h < e; ++h)
      {
        halves[h].reserve(2 * n / leafSize + 2); // leaves of at least leafSize / 2 of n / 2 points
        buildSubtree(entries, h == 0 ? 0 : middle, h == 0 ? middle : n, 1, leafSize, halves[h]);
      }
    });
    this->Nodes.reserve(1 + halves[0].size() + halves[1].size());
    this->Nodes.push_back({ box, 1, 0 });
    this->Nodes.resize(3);
    for (int h = 0; h < 2; ++h)
    {
      // The half's root becomes child h; its other nodes follow the nodes placed so far.
      const int offset = static_cast<int>(this->Nodes.size()) - 1;
      for (std::size_t k = 0; k < halves[h].size(); ++k)
      {
        HierarchyNode node = halves[h][k];
        if (node.count == 0)
        {
          node.first += offset;
        }
        if (k == 0)
        {
          this->Nodes[1 + h] = node;
        }
        else
        {
          this->Nodes.push_back(node);
        }
      }
    }
  }
}

PointTree::Hit PointTree::nearest(const Vec3& x, double maxSquaredDistance, bool apart) const
{
  Hit hit;
  hit.squaredDistance = maxSquaredDistance;
  searchNearest(this->Nodes, x, hit.squaredDistance, [&](int k) {
    const double d2 = (this->Sorted[k].point - x).squaredNorm();
    if (d2 < hit.squaredDistance && (d2 > 0 || !apart))
    {
      hit = { this->Sorted[k].id, d2 };
    }
  });
  return hit;
}

} // namespace shrinkwrap
