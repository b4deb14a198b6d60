#include "Distance/AABBTree.h"
#include "Common/Parallel.h"

#include <algorithm>
#include <numeric>

namespace shrinkwrap
{

// Buffers of the split search, reused from node to node (a tree has tens of thousands of nodes).
struct AABBTree::SplitScratch
{
  std::vector<double> coords, cuts, rightCost;
  std::vector<int> histogram, firstCut, binCount;
  std::vector<Box> binBox;
};

namespace
{

// Split candidates along one axis of the centroid range [lo, hi]: uniform samples, then samples
// at equal steps of the cumulative centroid count, which Hunt et al. [4] show places them where the
// SAH cost changes most.
void splitCandidates(const std::vector<double>& coords, int count, double lo, double hi,
  int uniform, int adaptive, std::vector<int>& histogram, std::vector<double>& candidates)
{
  const double width = (hi - lo) / uniform;
  candidates.clear();
  for (int k = 1; k < uniform; ++k)
  {
    candidates.push_back(lo + k * width);
  }
  if (adaptive == 0)
  {
    // Ascending already; equal only where the width is below the coordinates' rounding.
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    return;
  }
  histogram.assign(uniform, 0);
  for (int k = 0; k < count; ++k)
  {
    ++histogram[std::min(uniform - 1, static_cast<int>((coords[k] - lo) / width))];
  }
  const double n = static_cast<double>(count);
  int bin = 0;
  double below = 0; // centroids left of bin
  for (int r = 1; r <= adaptive; ++r)
  {
    const double target = r * n / (adaptive + 1);
    while (bin < uniform - 1 && below + histogram[bin] < target)
    {
      below += histogram[bin++];
    }
    const double fraction = histogram[bin] > 0 ? (target - below) / histogram[bin] : 0.5;
    candidates.push_back(lo + (bin + std::clamp(fraction, 0.0, 1.0)) * width);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
}
} // namespace

AABBTree::AABBTree(const TriangleSoup& soup, const AABBTreeSettings& settings)
{
  LargeVector<Prim> prims(soup.triangles.size());
  for (std::size_t t = 0; t < prims.size(); ++t)
  {
    const Box box = Box::around(soup.points, soup.triangles[t]);
    prims[t] = { box, box.center(), static_cast<int>(t) };
  }
  this->Nodes.reserve(2 * prims.size() / std::max(1, settings.leafSize) + 1);
  this->Nodes.push_back({ Box(), 0, 0 }); // the root exists even for an empty soup
  if (prims.empty())
  {
    return;
  }
  this->buildInParallel(prims, settings);
  this->Order.resize(prims.size());
  this->Corners.resize(prims.size());
  this->Planes.resize(prims.size());
  for (std::size_t k = 0; k < prims.size(); ++k)
  {
    const auto& tri = soup.triangles[prims[k].id];
    this->Order[k] = prims[k].id;
    this->Corners[k] = { soup.points[tri[0]], soup.points[tri[1]], soup.points[tri[2]] };
    const auto& c = this->Corners[k];
    const Vec3 n = (c[1] - c[0]).cross(c[2] - c[0]);
    const double length = n.norm();
    this->Planes[k] =
      length > 0 && std::isfinite(length) ? Plane{ n / length, n.dot(c[0]) / length } : Plane{};
  }
}

void AABBTree::build(HierarchyNodes& nodes, LargeVector<Prim>& prims, int index, int begin, int end,
  int depth, const AABBTreeSettings& s, SplitScratch& scratch, std::vector<Subtree>* deferred)
{
  Box box, centroids;
  for (int k = begin; k < end; ++k)
  {
    box.extend(prims[k].box);
    centroids.extend(prims[k].centroid);
  }
  const int count = end - begin;
  if (deferred && count <= s.parallelSubtreeSize)
  {
    deferred->push_back({ index, begin, end, depth });
    return;
  }
  const int mid = count > s.leafSize && depth < kMaxHierarchyDepth
    ? this->splitPosition(prims, begin, end, centroids, s, scratch)
    : -1;
  if (mid <= begin || mid >= end)
  {
    nodes[index] = { box, begin, count };
    return;
  }
  // Siblings sit next to each other, so an inner node needs one child index.
  const int left = static_cast<int>(nodes.size());
  nodes[index] = { box, left, 0 };
  nodes.resize(nodes.size() + 2);
  this->build(nodes, prims, left, begin, mid, depth + 1, s, scratch, deferred);
  this->build(nodes, prims, left + 1, mid, end, depth + 1, s, scratch, deferred);
}

void AABBTree::buildInParallel(LargeVector<Prim>& prims, const AABBTreeSettings& s)
{
  // The top of the tree first, leaving subtrees of at most parallelSubtreeSize triangles for later;
  // then those subtrees side by side, each in a node list of its own, appended at the end.
  std::vector<Subtree> subtrees;
  SplitScratch scratch;
  this->build(this->Nodes, prims, 0, 0, static_cast<int>(prims.size()), 1, s, scratch, &subtrees);
  std::vector<HierarchyNodes> parts(subtrees.size());
  parallelFor(0, static_cast<int>(subtrees.size()), 1, [&](int b, int e) {
    for (int t = b; t < e; ++t)
    {
      AABBTree local;
      SplitScratch localScratch;
      local.Nodes.assign(1, Node{});
      const Subtree& st = subtrees[t];
      local.build(local.Nodes, prims, 0, st.begin, st.end, st.depth, s, localScratch, nullptr);
      parts[t] = std::move(local.Nodes);
    }
  });
  for (std::size_t t = 0; t < subtrees.size(); ++t)
  {
    // Local node n > 0 lands at offset + n - 1; the local root replaces the reserved slot.
    const int offset = static_cast<int>(this->Nodes.size());
    for (std::size_t n = 0; n < parts[t].size(); ++n)
    {
      Node node = parts[t][n];
      if (node.count == 0)
      {
        node.first += offset - 1;
      }
      if (n == 0)
      {
        this->Nodes[subtrees[t].index] = node;
      }
      else
      {
        this->Nodes.push_back(node);
      }
    }
  }
}

namespace
{
// The cheapest cut between bins by the surface-area heuristic: its cost and the first bin to its
// right; an infinite cost where no cut leaves primitives on both sides.
std::pair<double, int> cheapestCut(const std::vector<int>& binCount, const std::vector<Box>& binBox,
  int count, std::vector<double>& rightCost)
{
  const int bins = static_cast<int>(binCount.size());
  rightCost.assign(bins, 0);
  Box right;
  int nRight = 0;
  for (int b = bins - 1; b > 0; --b)
  {
    right.extend(binBox[b]);
    nRight += binCount[b];
    rightCost[b] = nRight ? right.halfArea() * nRight : 0;
  }
  std::pair<double, int> best(std::numeric_limits<double>::infinity(), -1);
  Box left;
  int nLeft = 0;
  for (int b = 1; b < bins; ++b)
  {
    left.extend(binBox[b - 1]);
    nLeft += binCount[b - 1];
    if (nLeft == 0 || nLeft == count)
    {
      continue;
    }
    const double cost = left.halfArea() * nLeft + rightCost[b];
    if (cost < best.first)
    {
      best = { cost, b };
    }
  }
  return best;
}
} // namespace

int AABBTree::splitPosition(LargeVector<Prim>& prims, int begin, int end, const Box& centroids,
  const AABBTreeSettings& s, SplitScratch& scratch) const
{
  const int count = end - begin;
  double bestCost = std::numeric_limits<double>::infinity();
  int bestAxis = -1;
  double bestSplit = 0;
  std::vector<double>& coords = scratch.coords;
  coords.resize(std::max<std::size_t>(coords.size(), count));
  for (int axis = 0; axis < 3; ++axis)
  {
    const double lo = centroids.min[axis], hi = centroids.max[axis];
    if (!(hi > lo))
    {
      continue;
    }
    for (int k = 0; k < count; ++k)
    {
      coords[k] = prims[begin + k].centroid[axis];
    }
    // Small nodes gain little from the adaptive samples; they take the uniform ones only.
    const int adaptive = count > 16 * s.uniformSamples ? s.adaptiveSamples : 0;
    std::vector<double>& cuts = scratch.cuts;
    splitCandidates(coords, count, lo, hi, s.uniformSamples, adaptive, scratch.histogram, cuts);
    // Fine bins between consecutive cuts; counts and boxes per bin give the exact SAH at each cut.
    // A centroid's uniform bin is found by division; the few adaptive cuts inside it by a short
    // scan.
    const int bins = static_cast<int>(cuts.size()) + 1;
    const double width = (hi - lo) / s.uniformSamples;
    std::vector<int>& firstCut = scratch.firstCut;
    firstCut.resize(s.uniformSamples);
    for (int u = 0; u < s.uniformSamples; ++u)
    {
      firstCut[u] =
        static_cast<int>(std::lower_bound(cuts.begin(), cuts.end(), lo + u * width) - cuts.begin());
    }
    std::vector<int>& binCount = scratch.binCount;
    std::vector<Box>& binBox = scratch.binBox;
    binCount.assign(bins, 0);
    binBox.assign(bins, Box());
    for (int k = 0; k < count; ++k)
    {
      const int u = std::min(s.uniformSamples - 1, static_cast<int>((coords[k] - lo) / width));
      int b = firstCut[u];
      while (b < bins - 1 && cuts[b] <= coords[k])
      {
        ++b;
      }
      ++binCount[b];
      binBox[b].extend(prims[begin + k].box);
    }
    const std::pair<double, int> cut = cheapestCut(binCount, binBox, count, scratch.rightCost);
    if (cut.first < bestCost)
    {
      bestCost = cut.first;
      bestAxis = axis;
      bestSplit = cuts[cut.second - 1];
    }
  }
  if (bestAxis < 0)
  {
    // All centroids coincide: split in the middle of the list.
    return begin + count / 2;
  }
  auto it = std::partition(prims.begin() + begin, prims.begin() + end,
    [&](const Prim& p) { return p.centroid[bestAxis] < bestSplit; });
  return static_cast<int>(it - prims.begin());
}

ClosestHit AABBTree::closestPoint(const Vec3& p, double maxSquaredDistance) const
{
  ClosestHit hit;
  hit.squaredDistance = maxSquaredDistance;
  if (this->Order.empty())
  {
    return hit;
  }
  searchNearest(this->Nodes, p, hit.squaredDistance, [&](int k) {
    // No point of a triangle is nearer than its plane.
    const double h = this->Planes[k].normal.dot(p) - this->Planes[k].offset;
    if (h * h >= hit.squaredDistance)
    {
      return;
    }
    const auto& c = this->Corners[k];
    const TrianglePoint tp = closestPointOnTriangle(p, c[0], c[1], c[2]);
    const double d2 = (tp.point - p).squaredNorm();
    if (d2 < hit.squaredDistance)
    {
      hit = { this->Order[k], d2, tp.point, tp.feature };
    }
  });
  return hit;
}

} // namespace shrinkwrap
