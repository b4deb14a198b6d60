// The paper's triangle soup (Section 2.1): points and triangles indexing them, the one shape in
// which meshes enter and leave the core. Nothing is assumed of its topology (non-manifold and
// duplicate-point meshes are accepted); SurfaceMesh::build checks that a soup is a closed surface.
#ifndef ShrinkWrap_TriangleSoup_h
#define ShrinkWrap_TriangleSoup_h

#include "Common/Box.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct TriangleSoup
{
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>>
    triangles; // counter-clockwise seen from outside, where that means something

  Box bounds() const; // of the points that triangles use
  bool allFinite() const;
  // Largest triangle area; zero when every triangle is degenerate.
  double maxTriangleArea() const;
  // The triangles' total area (of those whose ids are all valid).
  double area() const;
};

} // namespace shrinkwrap

#endif
