#include "SelfIntersections.h"

#include "Box.h"
#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <unordered_map>

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

// Whether triangles s and t cross, ignoring what they share: with one shared vertex only the edges
// opposite it can cross the other triangle; with two (a shared edge) they are neighbours.
bool crosses(const std::vector<Vec3>& x, const std::array<int, 3>& s, const std::array<int, 3>& t)
{
  int shared = 0;
  for (int a : s)
  {
    shared += a == t[0] || a == t[1] || a == t[2];
  }
  if (shared >= 2)
  {
    return false;
  }
  auto edgesThrough = [&](const std::array<int, 3>& e, const std::array<int, 3>& f) {
    for (int k = 0; k < 3; ++k)
    {
      const int p = e[k], q = e[(k + 1) % 3];
      const bool touches = p == f[0] || p == f[1] || p == f[2] || q == f[0] || q == f[1] || q == f[2];
      if (!touches && segmentCrosses(x[p], x[q], x[f[0]], x[f[1]], x[f[2]]))
      {
        return true;
      }
    }
    return false;
  };
  return edgesThrough(s, t) || edgesThrough(t, s);
}
} // namespace

SelfIntersections findSelfIntersections(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  SelfIntersections found;
  const int nt = static_cast<int>(triangles.size());
  found.intersecting.assign(nt, 0);
  if (nt < 2)
  {
    return found;
  }
  Box all;
  double edges = 0;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      all.extend(x[t[k]]);
      edges += (x[t[k]] - x[t[(k + 1) % 3]]).norm();
    }
  }
  const double cell = std::max(2 * edges / (3.0 * nt), 1e-9 * all.diagonal());
  if (!(cell > 0) || !std::isfinite(cell) || !std::isfinite(all.diagonal()))
  {
    return found;
  }
  // Triangles per grid cell (cells keyed by their integer coordinates).
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
  };
  struct Cell
  {
    std::array<std::int64_t, 3> at;
    std::vector<int> triangles;
  };
  std::unordered_map<std::int64_t, std::vector<Cell>> grid;
  std::vector<std::array<std::int64_t, 6>> ranges(nt);
  for (int t = 0; t < nt; ++t)
  {
    Box b;
    for (int v : triangles[t])
    {
      b.extend(x[v]);
    }
    auto& r = ranges[t];
    for (int a = 0; a < 3; ++a)
    {
      r[a] = static_cast<std::int64_t>(std::floor((b.min[a] - all.min[a]) / cell));
      r[a + 3] = static_cast<std::int64_t>(std::floor((b.max[a] - all.min[a]) / cell));
    }
    for (std::int64_t k = r[2]; k <= r[5]; ++k)
      for (std::int64_t j = r[1]; j <= r[4]; ++j)
        for (std::int64_t i = r[0]; i <= r[3]; ++i)
        {
          auto& bucket = grid[key(i, j, k)];
          auto c = std::find_if(bucket.begin(), bucket.end(), [&](const Cell& e) { return e.at == std::array<std::int64_t, 3>{ i, j, k }; });
          if (c == bucket.end())
          {
            bucket.push_back({ { i, j, k }, {} });
            c = bucket.end() - 1;
          }
          c->triangles.push_back(t);
        }
  }
  std::vector<const Cell*> cells;
  for (const auto& bucket : grid)
  {
    for (const Cell& c : bucket.second)
    {
      cells.push_back(&c);
    }
  }
  // A pair is tested in the first cell (lowest i, j, k) both boxes share, so once.
  auto firstShared = [&](int s, int t) {
    std::array<std::int64_t, 3> at;
    for (int a = 0; a < 3; ++a)
    {
      at[a] = std::max(ranges[s][a], ranges[t][a]);
    }
    return at;
  };
  std::mutex lock;
  parallelFor(0, static_cast<int>(cells.size()), [&](int begin, int end) {
    std::vector<std::pair<int, int>> crossing;
    for (int c = begin; c < end; ++c)
    {
      const auto& list = cells[c]->triangles;
      for (std::size_t p = 0; p < list.size(); ++p)
      {
        for (std::size_t q = p + 1; q < list.size(); ++q)
        {
          const int s = list[p], t = list[q];
          if (firstShared(s, t) == cells[c]->at && crosses(x, triangles[s], triangles[t]))
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

} // namespace shrinkwrap
