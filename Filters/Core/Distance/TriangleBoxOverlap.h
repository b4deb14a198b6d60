// Exact triangle / axis-aligned box overlap by the separating axis theorem (Akenine-Moeller 2001):
// 3 box normals, the triangle normal and the 9 edge cross products. Decides which octree cells the
// surface touches (Algorithm 2, line 6).
#ifndef ShrinkWrap_TriangleBoxOverlap_h
#define ShrinkWrap_TriangleBoxOverlap_h

#include "Common/Box.h"

#include <cmath>

namespace shrinkwrap
{

namespace detail
{
// Is axis a a separating axis for the triangle (v0,v1,v2) and the box of half size h at the origin?
inline bool separates(const Vec3& a, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& h)
{
  const double p0 = a.dot(v0), p1 = a.dot(v1), p2 = a.dot(v2);
  const double r = h.x() * std::abs(a.x()) + h.y() * std::abs(a.y()) + h.z() * std::abs(a.z());
  return std::min({ p0, p1, p2 }) > r || std::max({ p0, p1, p2 }) < -r;
}
} // namespace detail

inline bool triangleOverlapsBox(const Vec3& a, const Vec3& b, const Vec3& c, const Box& box)
{
  const Vec3 center = box.center();
  const Vec3 h = 0.5 * box.size();
  const Vec3 v0 = a - center, v1 = b - center, v2 = c - center;
  // Box face normals: bounding-box test.
  for (int k = 0; k < 3; ++k)
  {
    if (std::min({ v0[k], v1[k], v2[k] }) > h[k] || std::max({ v0[k], v1[k], v2[k] }) < -h[k])
    {
      return false;
    }
  }
  const Vec3 e[3] = { v1 - v0, v2 - v1, v0 - v2 };
  for (const Vec3& edge : e)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 axis = Vec3::Unit(k).cross(edge);
      if (detail::separates(axis, v0, v1, v2, h))
      {
        return false;
      }
    }
  }
  // Triangle plane (a zero normal of a degenerate triangle separates nothing).
  return !detail::separates(e[0].cross(e[1]), v0, v1, v2, h);
}

} // namespace shrinkwrap

#endif
