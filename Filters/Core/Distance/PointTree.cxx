#include "PointTree.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

PointTree::PointTree(const std::vector<Vec3>& points, int leafSize)
{
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    if (points[i].allFinite())
    {
      this->Ids.push_back(static_cast<int>(i));
    }
  }
  if (this->Ids.empty())
  {
    return;
  }
  leafSize = std::max(leafSize, 1);
  struct Range
  {
    int node, begin, end, depth;
  };
  std::vector<Range> pending{ { 0, 0, static_cast<int>(this->Ids.size()), 0 } };
  this->Nodes.push_back({});
  while (!pending.empty())
  {
    const Range r = pending.back();
    pending.pop_back();
    Box box;
    for (int k = r.begin; k < r.end; ++k)
    {
      box.extend(points[this->Ids[k]]);
    }
    this->Nodes[r.node].box = box;
    if (r.end - r.begin <= leafSize || r.depth + 1 >= kMaxHierarchyDepth)
    {
      this->Nodes[r.node].first = r.begin;
      this->Nodes[r.node].count = r.end - r.begin;
      continue;
    }
    int axis = 0;
    box.size().maxCoeff(&axis);
    const int middle = r.begin + (r.end - r.begin) / 2;
    std::nth_element(this->Ids.begin() + r.begin, this->Ids.begin() + middle, this->Ids.begin() + r.end,
      [&](int a, int b) { return points[a][axis] < points[b][axis]; });
    const int left = static_cast<int>(this->Nodes.size());
    this->Nodes[r.node].first = left;
    this->Nodes[r.node].count = 0;
    this->Nodes.resize(this->Nodes.size() + 2);
    pending.push_back({ left, r.begin, middle, r.depth + 1 });
    pending.push_back({ left + 1, middle, r.end, r.depth + 1 });
  }
  this->Sorted.reserve(this->Ids.size());
  for (const int id : this->Ids)
  {
    this->Sorted.push_back(points[id]);
  }
}

PointTree::Hit PointTree::nearest(const Vec3& x, double maxSquaredDistance, bool apart) const
{
  Hit hit;
  hit.squaredDistance = maxSquaredDistance;
  searchNearest(this->Nodes, x, hit.squaredDistance, [&](int k) {
    const double d2 = (this->Sorted[k] - x).squaredNorm();
    if (d2 < hit.squaredDistance && (d2 > 0 || !apart))
    {
      hit = { this->Ids[k], d2 };
    }
  });
  return hit;
}

} // namespace shrinkwrap
