// Where a closed triangle surface passes through itself: pairs of triangles that cross, not counting
// the vertices and edges they share. The wrap must never output one (issue #10). Candidates come from a
// grid of triangle boxes (TriangleGrid, cells about two mean edge lengths wide); two triangles cross
// when an edge of one passes through the other, decided by the signs of tetrahedron volumes.
// Coplanar overlaps and mere touching (measure zero in an evolution) are not reported.
#ifndef ShrinkWrap_SelfIntersections_h
#define ShrinkWrap_SelfIntersections_h

#include "Box.h"
#include "Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shrinkwrap
{

struct SelfIntersections
{
  long long pairs = 0;             // crossing triangle pairs
  std::vector<char> intersecting;  // per triangle: 1 if it crosses another
};

SelfIntersections findSelfIntersections(
  const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);

// Fronts stop where they meet: the vertices of triangles that cross at `next` but did not at
// `previous` (the same triangles) go back to their `previous` positions, again until no new crossing
// is left (at worst every vertex of a crossing stays where it was). Returns how many were held.
int holdNewCrossings(const std::vector<Vec3>& previous, std::vector<Vec3>& next,
  const std::vector<std::array<int, 3>>& triangles);

// The triangles of a surface binned in a uniform grid of their boxes.
class TriangleGrid
{
public:
  TriangleGrid(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);
  bool empty() const { return this->Entries.empty(); }
  // Calls f(triangle) for every triangle whose box overlaps `box` (once each).
  template <typename F>
  void forEachNear(const Box& box, F&& f) const;

  // (cell key, triangle), sorted by key; cells keyed 21 bits an axis.
  std::vector<std::pair<std::uint64_t, int>> Entries;
  std::vector<Box> Boxes;
  std::vector<std::array<std::uint64_t, 6>> Ranges; // per triangle: first and last cell per axis
  Vec3 Origin = Vec3::Zero();
  double Cell = 0;
  std::array<std::uint64_t, 6> rangeOf(const Box& box) const;
  static std::uint64_t key(std::uint64_t i, std::uint64_t j, std::uint64_t k) { return (k << 42) | (j << 21) | i; }
};

// For the local edits of a pass (collapses): whether the fan of triangles (m, u, w) that merging a and b
// at m would make crosses the rest of the surface as it was when the pass began.
class CrossingGuard
{
public:
  CrossingGuard(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);
  // rim: the (u, w) of each new triangle (m, u, w).
  bool fanCrosses(const Vec3& m, const std::vector<std::array<int, 2>>& rim, int a, int b) const;

private:
  const std::vector<Vec3>& Points;
  const std::vector<std::array<int, 3>>& Triangles;
  TriangleGrid Grid;
};

template <typename F>
void TriangleGrid::forEachNear(const Box& box, F&& f) const
{
  if (this->Entries.empty())
  {
    return;
  }
  const auto r = this->rangeOf(box);
  std::vector<int> seen;
  for (std::uint64_t k = r[2]; k <= r[5]; ++k)
    for (std::uint64_t j = r[1]; j <= r[4]; ++j)
      for (std::uint64_t i = r[0]; i <= r[3]; ++i)
      {
        const std::uint64_t at = key(i, j, k);
        auto e = std::lower_bound(this->Entries.begin(), this->Entries.end(), std::make_pair(at, -1));
        for (; e != this->Entries.end() && e->first == at; ++e)
        {
          if (this->Boxes[e->second].overlaps(box) &&
            std::find(seen.begin(), seen.end(), e->second) == seen.end())
          {
            seen.push_back(e->second);
            f(e->second);
          }
        }
      }
}

} // namespace shrinkwrap

#endif
