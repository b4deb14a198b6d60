// Where a closed triangle surface passes through itself: pairs of triangles that cross, not counting
// the vertices and edges they share. The wrap must never output one (issue #10); the filter reports
// any that remain. Candidates come from a uniform grid of triangle boxes (cells about two mean edge
// lengths wide); two triangles cross when an edge of one passes through the other, decided by the
// signs of tetrahedron volumes. Coplanar overlaps (measure zero in an evolution) are not reported.
#ifndef ShrinkWrap_SelfIntersections_h
#define ShrinkWrap_SelfIntersections_h

#include "Vec3.h"

#include <array>
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

} // namespace shrinkwrap

#endif
