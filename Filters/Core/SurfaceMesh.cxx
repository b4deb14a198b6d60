#include "SurfaceMesh.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

namespace shrinkwrap
{

namespace
{
// A directed edge a -> b of triangle t, whose third vertex follows b.
struct Corner
{
  int a, b, c, triangle;
};
} // namespace

bool SurfaceMesh::build(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
  SurfaceMesh& mesh, std::string& error)
{
  const int nv = static_cast<int>(points.size());
  const int nt = static_cast<int>(triangles.size());
  std::ostringstream why;
  if (nv == 0 || nt == 0)
  {
    error = "the surface is empty";
    return false;
  }
  for (const auto& p : points)
  {
    if (!p.allFinite())
    {
      error = "the surface has NaN or infinite coordinates";
      return false;
    }
  }
  // Corners grouped by vertex: at vertex a, triangle (a, b, c) leads from neighbour b to neighbour c.
  // Bucketed by a (counting sort), then each small bucket sorted by b: linear time, as this runs
  // again after every round of edge flips.
  std::vector<int> bucket(nv + 1, 0);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
      if (a < 0 || a >= nv || b < 0 || b >= nv || c < 0 || c >= nv)
      {
        error = "a triangle refers to a vertex that does not exist";
        return false;
      }
      if (a == b || b == c || c == a)
      {
        why << "triangle " << t << " repeats a vertex";
        error = why.str();
        return false;
      }
      ++bucket[a + 1];
    }
  }
  for (int v = 0; v < nv; ++v)
  {
    bucket[v + 1] += bucket[v];
  }
  std::vector<Corner> corners(3 * static_cast<std::size_t>(nt));
  {
    std::vector<int> fill(bucket.begin(), bucket.end() - 1);
    for (int t = 0; t < nt; ++t)
    {
      const auto& tri = triangles[t];
      for (int k = 0; k < 3; ++k)
      {
        corners[fill[tri[k]]++] = { tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3], t };
      }
    }
  }
  for (int v = 0; v < nv; ++v)
  {
    std::sort(corners.begin() + bucket[v], corners.begin() + bucket[v + 1],
      [](const Corner& x, const Corner& y) { return x.b < y.b; });
  }

  mesh.Triangles = triangles;
  mesh.InitialPoints = points;
  mesh.RingStart.assign(nv + 1, 0);
  mesh.Ring.resize(corners.size());
  mesh.RingTriangle.resize(corners.size());
  std::size_t first = 0;
  for (int v = 0; v < nv; ++v)
  {
    std::size_t last = first;
    while (last < corners.size() && corners[last].a == v)
    {
      ++last;
    }
    const int m = static_cast<int>(last - first);
    if (m == 0)
    {
      why << "vertex " << v << " belongs to no triangle";
      error = why.str();
      return false;
    }
    // Walk the fan: from neighbour b, the corner starting at b leads to c, which must start the next.
    auto find = [&](int b) -> const Corner* {
      auto it = std::lower_bound(corners.begin() + first, corners.begin() + last, b,
        [](const Corner& x, int key) { return x.b < key; });
      return it != corners.begin() + last && it->b == b ? &*it : nullptr;
    };
    if (std::adjacent_find(corners.begin() + first, corners.begin() + last,
          [](const Corner& x, const Corner& y) { return x.b == y.b; }) != corners.begin() + last)
    {
      why << "an edge at vertex " << v << " is used by more than two triangles or twice in one direction";
      error = why.str();
      return false;
    }
    mesh.RingStart[v + 1] = mesh.RingStart[v] + m;
    const Corner* corner = &corners[first];
    for (int p = 0; p < m; ++p)
    {
      if (p > 0 && corner->b == corners[first].b)
      {
        why << "vertex " << v << " is non-manifold (its triangles form more than one fan)";
        error = why.str();
        return false;
      }
      mesh.Ring[mesh.RingStart[v] + p] = corner->b;
      mesh.RingTriangle[mesh.RingStart[v] + p] = corner->triangle;
      const Corner* following = find(corner->c);
      if (!following)
      {
        why << "the surface is open or inconsistently oriented at the edge (" << v << ", " << corner->c << ")";
        error = why.str();
        return false;
      }
      corner = following;
    }
    if (corner != &corners[first])
    {
      why << "vertex " << v << " is non-manifold (its triangles form more than one fan)";
      error = why.str();
      return false;
    }
    first = last;
  }
  return true;
}

} // namespace shrinkwrap
