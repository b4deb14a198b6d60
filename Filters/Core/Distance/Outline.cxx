#include "Distance/Outline.h"
#include "Common/Parallel.h"

#include "Distance/TriangleBoxOverlap.h"

#include <cmath>
#include <iterator>
#include <numeric>

namespace shrinkwrap
{

namespace
{
struct OctreeNode
{
  std::array<int, 3> lo; // first cell index on each axis
  int size;              // cells per side, a power of two
  std::vector<int> triangles;
};

Box cellBox(const GridLattice& lattice, const std::array<int, 3>& lo, int size)
{
  // Grown by a hair so that a triangle lying exactly on a cell face touches both cells.
  const Vec3 pad = 1e-7 * lattice.spacing;
  Box b;
  b.min = lattice.position(lo[0], lo[1], lo[2]) - pad;
  b.max = lattice.position(lo[0] + size, lo[1] + size, lo[2] + size) + pad;
  return b;
}

// Algorithm 2, lines 3-11 for one node: the children that the surface touches, with their
// triangles. A triangle is tested only against the children its box reaches (a margin wider than
// the cells' pad: the exact test decides).
void subdivide(const TriangleSoup& soup, const GridLattice& lattice, const std::array<int, 3>& last,
  const OctreeNode& node, std::vector<OctreeNode>& children)
{
  const int half = node.size / 2;
  std::array<OctreeNode, 8> child;
  std::array<Box, 8> box;
  std::array<bool, 8> inGrid;
  for (int octant = 0; octant < 8; ++octant)
  {
    child[octant] =
      OctreeNode{ { node.lo[0] + (octant & 1) * half, node.lo[1] + ((octant >> 1) & 1) * half,
                    node.lo[2] + ((octant >> 2) & 1) * half },
        half, {} };
    inGrid[octant] = child[octant].lo[0] <= last[0] && child[octant].lo[1] <= last[1] &&
      child[octant].lo[2] <= last[2];
    box[octant] = cellBox(lattice, child[octant].lo, half);
  }
  const Vec3 mid = lattice.position(node.lo[0] + half, node.lo[1] + half, node.lo[2] + half);
  const Vec3 margin = 1e-5 * lattice.spacing;
  for (int t : node.triangles)
  {
    const auto& tri = soup.triangles[t];
    const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
    const Vec3 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    std::array<int, 3> sides; // per axis: bit 0 the lower half reached, bit 1 the upper
    for (int axis = 0; axis < 3; ++axis)
    {
      sides[axis] = (lo[axis] <= mid[axis] + margin[axis] ? 1 : 0) |
        (hi[axis] >= mid[axis] - margin[axis] ? 2 : 0);
    }
    for (int octant = 0; octant < 8; ++octant)
    {
      const bool reached = (sides[0] >> (octant & 1) & 1) &&
        (sides[1] >> ((octant >> 1) & 1) & 1) && (sides[2] >> ((octant >> 2) & 1) & 1);
      const Box& cell = box[octant];
      // A triangle inside the child's box overlaps it: no separating axis to look for.
      const bool inside =
        (lo.array() >= cell.min.array()).all() && (hi.array() <= cell.max.array()).all();
      if (reached && inGrid[octant] && (inside || triangleOverlapsBox(a, b, c, cell)))
      {
        child[octant].triangles.push_back(t);
      }
    }
  }
  for (int octant = 0; octant < 8; ++octant)
  {
    if (!child[octant].triangles.empty())
    {
      children.push_back(std::move(child[octant]));
    }
  }
}
} // namespace

bool outlineCells(
  const TriangleSoup& soup, const GridLattice& lattice, const Progress& progress, IndexList& cells)
{
  cells.clear();
  const std::array<int, 3> last = { lattice.dims[0] - 2, lattice.dims[1] - 2, lattice.dims[2] - 2 };
  const Box bounds = soup.bounds();
  if (bounds.empty() || last[0] < 0 || last[1] < 0 || last[2] < 0)
  {
    return true;
  }
  // Algorithm 2, line 1: a cube of 2^L cells around the mesh, aligned with the grid.
  std::array<int, 3> lo, hi;
  for (int a = 0; a < 3; ++a)
  {
    const double h = lattice.spacing[a];
    // Clamped before the cast: a mesh far outside an explicit grid is beyond the range of int.
    const double first = std::floor((bounds.min[a] - lattice.origin[a]) / h) - 1;
    const double end = std::floor((bounds.max[a] - lattice.origin[a]) / h) + 1;
    lo[a] = static_cast<int>(std::clamp(first, 0.0, static_cast<double>(last[a])));
    hi[a] = static_cast<int>(std::clamp(end, 0.0, static_cast<double>(last[a])));
  }
  int size = 1;
  while (size < std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] }) + 1)
  {
    size *= 2;
  }
  std::vector<OctreeNode> level(1, OctreeNode{ lo, size, {} });
  level[0].triangles.resize(soup.triangles.size());
  std::iota(level[0].triangles.begin(), level[0].triangles.end(), 0);

  int levels = 0;
  for (int s = size; s > 1; s /= 2)
  {
    ++levels;
  }
  for (int depth = 0; size > 1; ++depth, size /= 2)
  {
    ThreadLocal<std::vector<OctreeNode>> next;
    parallelFor(0, static_cast<long long>(level.size()), 1, [&](long long b, long long e) {
      auto& out = next.local();
      for (long long n = b; n < e; ++n)
      {
        subdivide(soup, lattice, last, level[n], out);
      }
    });
    level.clear();
    next.forEach([&](std::vector<OctreeNode>& part) {
      std::move(part.begin(), part.end(), std::back_inserter(level));
    });
    if (!progress.report(static_cast<double>(depth + 1) / levels))
    {
      return false;
    }
  }
  cells.reserve(level.size());
  for (const OctreeNode& leaf : level)
  {
    cells.push_back(lattice.index(leaf.lo[0], leaf.lo[1], leaf.lo[2]));
  }
  return true;
}

} // namespace shrinkwrap
