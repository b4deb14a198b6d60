#include "SelfIntersections.h"

#include "Box.h"
#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>

namespace shrinkwrap
{

namespace
{
int sign(double v)
{
  return (v > 0) - (v < 0);
}

// The sign of the volume of the tetrahedron (a, b, c, d).
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return sign(tripleProduct(b - a, c - a, d - a));
}

// Whether the open segment pq passes through the triangle abc (strictly on both sides of its plane).
bool segmentCrosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const int sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq)
  {
    return false;
  }
  const int s1 = orientation(p, q, a, b), s2 = orientation(p, q, b, c), s3 = orientation(p, q, c, a);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0 && (s1 | s2 | s3)) || (s1 <= 0 && s2 <= 0 && s3 <= 0 && (s1 | s2 | s3));
}

// A triangle by its corners and their vertex ids (-1: a new point, shared with nothing), with its
// plane n . y = offset (|n| = 1) for the cheap first test of a pair.
struct Facet
{
  std::array<Vec3, 3> p;
  std::array<int, 3> id;
  Vec3 n;
  double offset;
};

Facet facetAt(const std::array<Vec3, 3>& p, const std::array<int, 3>& id)
{
  Facet f{ p, id, (p[1] - p[0]).cross(p[2] - p[0]), 0 };
  const double length = f.n.norm();
  f.n = length > 0 ? Vec3(f.n / length) : Vec3::Zero();
  f.offset = f.n.dot(p[0]);
  return f;
}

Facet facetOf(const std::vector<Vec3>& x, const std::array<int, 3>& t)
{
  return facetAt({ x[t[0]], x[t[1]], x[t[2]] }, t);
}

bool has(const std::array<int, 3>& ids, int v)
{
  return v >= 0 && (v == ids[0] || v == ids[1] || v == ids[2]);
}

// Whether all three corners of f lie clearly (beyond `margin`) on one side of the plane of e, so that
// the two cannot cross.
bool oneSide(const Facet& e, const Facet& f, double margin)
{
  const double a = e.n.dot(f.p[0]) - e.offset, b = e.n.dot(f.p[1]) - e.offset, c = e.n.dot(f.p[2]) - e.offset;
  return (a > margin && b > margin && c > margin) || (a < -margin && b < -margin && c < -margin);
}

// Whether triangles s and t cross, ignoring what they share: with one shared vertex only the edges
// opposite it can cross the other triangle; with two (a shared edge) they are neighbours.
bool crosses(const Facet& s, const Facet& t, double margin)
{
  const int shared = has(t.id, s.id[0]) + has(t.id, s.id[1]) + has(t.id, s.id[2]);
  if (shared >= 2 || (shared == 0 && (oneSide(s, t, margin) || oneSide(t, s, margin))))
  {
    return false;
  }
  auto edgesThrough = [&](const Facet& e, const Facet& f) {
    for (int k = 0; k < 3; ++k)
    {
      const int q = (k + 1) % 3;
      if (!has(f.id, e.id[k]) && !has(f.id, e.id[q]) && segmentCrosses(e.p[k], e.p[q], f.p[0], f.p[1], f.p[2]))
      {
        return true;
      }
    }
    return false;
  };
  return edgesThrough(s, t) || edgesThrough(t, s);
}

// Closer to a plane than this goes the exact way (orientations) rather than the plane test.
double roundingMargin(const TriangleGrid& grid)
{
  return 1e-7 * grid.Cell;
}
} // namespace

TriangleGrid::TriangleGrid(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  const int nt = static_cast<int>(triangles.size());
  Box all;
  double edges = 0, longest = 0;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      all.extend(x[t[k]]);
      const double length = (x[t[k]] - x[t[(k + 1) % 3]]).norm();
      edges += length;
      longest = std::max(longest, length);
    }
  }
  // Two mean edges wide, and no triangle in more than 9 x 9 x 9 cells.
  this->Cell = nt > 0 ? std::max({ 2 * edges / (3.0 * nt), longest / 8, 1e-9 * all.diagonal() }) : 0;
  if (!(this->Cell > 0) || !std::isfinite(this->Cell) || !std::isfinite(all.diagonal()))
  {
    return;
  }
  this->Origin = all.min;
  this->Boxes.resize(nt);
  this->Ranges.resize(nt);
  this->Entries.reserve(8 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t)
  {
    Box& b = this->Boxes[t];
    for (int v : triangles[t])
    {
      b.extend(x[v]);
    }
    const auto& r = this->Ranges[t] = this->rangeOf(b);
    for (std::uint64_t k = r[2]; k <= r[5]; ++k)
      for (std::uint64_t j = r[1]; j <= r[4]; ++j)
        for (std::uint64_t i = r[0]; i <= r[3]; ++i)
        {
          this->Entries.emplace_back(key(i, j, k), t);
        }
  }
  std::sort(this->Entries.begin(), this->Entries.end());
}

std::array<std::uint64_t, 6> TriangleGrid::rangeOf(const Box& box) const
{
  std::array<std::uint64_t, 6> r{};
  for (int a = 0; a < 3; ++a)
  {
    // Clamped to the grid's 2^21 cells an axis (a query box may reach beyond the surface's).
    const auto cellOf = [&](double v) {
      return static_cast<std::uint64_t>(std::clamp((v - this->Origin[a]) / this->Cell, 0.0, 2097151.0));
    };
    r[a] = cellOf(box.min[a]);
    r[a + 3] = cellOf(box.max[a]);
  }
  return r;
}

SelfIntersections findSelfIntersections(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  SelfIntersections found;
  const int nt = static_cast<int>(triangles.size());
  found.intersecting.assign(nt, 0);
  const TriangleGrid grid(x, triangles);
  if (nt < 2 || grid.empty())
  {
    return found;
  }
  const auto& entries = grid.Entries;
  std::vector<std::size_t> runs; // where each cell's run of two or more begins, then its end
  for (std::size_t e = 0; e < entries.size();)
  {
    std::size_t end = e + 1;
    while (end < entries.size() && entries[end].first == entries[e].first)
    {
      ++end;
    }
    if (end - e > 1)
    {
      runs.push_back(e);
      runs.push_back(end);
    }
    e = end;
  }
  // A pair is tested in the first cell (lowest i, j, k) both boxes share, so once.
  const auto& ranges = grid.Ranges;
  auto firstShared = [&](int s, int t) {
    return TriangleGrid::key(std::max(ranges[s][0], ranges[t][0]), std::max(ranges[s][1], ranges[t][1]),
      std::max(ranges[s][2], ranges[t][2]));
  };
  std::vector<Facet> facets(nt);
  for (int t = 0; t < nt; ++t)
  {
    facets[t] = facetOf(x, triangles[t]);
  }
  const double margin = roundingMargin(grid);
  std::mutex lock;
  parallelFor(0, static_cast<int>(runs.size() / 2), [&](int begin, int end) {
    std::vector<std::pair<int, int>> crossing;
    for (int c = begin; c < end; ++c)
    {
      for (std::size_t p = runs[2 * c]; p < runs[2 * c + 1]; ++p)
      {
        for (std::size_t q = p + 1; q < runs[2 * c + 1]; ++q)
        {
          const int s = entries[p].second, t = entries[q].second;
          if (grid.Boxes[s].overlaps(grid.Boxes[t]) && firstShared(s, t) == entries[p].first &&
            crosses(facets[s], facets[t], margin))
          {
            crossing.emplace_back(s, t);
          }
        }
      }
    }
    std::lock_guard<std::mutex> guard(lock);
    for (const auto& st : crossing)
    {
      ++found.pairs;
      found.intersecting[st.first] = found.intersecting[st.second] = 1;
    }
  });
  return found;
}

CrossingGuard::CrossingGuard(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
  : Points(points)
  , Triangles(triangles)
  , Grid(points, triangles)
{
}

bool CrossingGuard::fanCrosses(const Vec3& m, const std::vector<std::array<int, 2>>& rim, int a, int b) const
{
  const std::vector<Vec3>& x = this->Points;
  for (const auto& uw : rim)
  {
    const Facet fan = facetAt({ m, x[uw[0]], x[uw[1]] }, { -1, uw[0], uw[1] });
    Box box;
    for (const Vec3& p : fan.p)
    {
      box.extend(p);
    }
    bool crossing = false;
    this->Grid.forEachNear(box, [&](int t) {
      const auto& tri = this->Triangles[t];
      if (!crossing && !has(tri, a) && !has(tri, b))
      {
        crossing = crosses(fan, facetOf(x, tri), roundingMargin(this->Grid));
      }
    });
    if (crossing)
    {
      return true;
    }
  }
  return false;
}

int holdNewCrossings(const std::vector<Vec3>& previous, std::vector<Vec3>& next,
  const std::vector<std::array<int, 3>>& triangles)
{
  SelfIntersections now = findSelfIntersections(next, triangles);
  if (now.pairs == 0)
  {
    return 0;
  }
  const SelfIntersections before = findSelfIntersections(previous, triangles);
  int held = 0;
  for (bool moved = true; moved && now.pairs > 0;)
  {
    moved = false;
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      if (!now.intersecting[t] || before.intersecting[t])
      {
        continue;
      }
      for (int v : triangles[t])
      {
        if (next[v] != previous[v])
        {
          next[v] = previous[v];
          ++held;
          moved = true;
        }
      }
    }
    if (moved)
    {
      now = findSelfIntersections(next, triangles);
    }
  }
  return held;
}

} // namespace shrinkwrap
