// Points and triangles indexing them: the one shape in which meshes enter and leave the core. As a
// triangle soup (Distance/TriangleSoup.h) nothing is assumed of it; as a triangle surface
// (Surface/TriangleSurface.h) it is closed and oriented.
#ifndef ShrinkWrap_IndexedTriangles_h
#define ShrinkWrap_IndexedTriangles_h

#include "Common/Box.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct IndexedTriangles
{
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles; // counter-clockwise seen from outside, where that means something

  Box bounds() const; // of the points that triangles use
  bool allFinite() const;
  // Largest triangle area; zero when every triangle is degenerate.
  double maxTriangleArea() const;
};

} // namespace shrinkwrap

#endif
