// Closest point on a triangle, with the feature (vertex, edge or face) it lies on.
// Ericson, Real-Time Collision Detection, 5.1.5: Voronoi regions tested in order, no square roots.
// The feature picks the angle-weighted pseudonormal that signs band nodes (Baerentzen & Aanaes 2005).
#ifndef ShrinkWrap_TriangleDistance_h
#define ShrinkWrap_TriangleDistance_h

#include "Common/Box.h"

#include <cstdint>

namespace shrinkwrap
{

// Vertex0..2, Edge01, Edge12, Edge20, Face.
enum class Feature : std::uint8_t
{
  Vertex0,
  Vertex1,
  Vertex2,
  Edge01,
  Edge12,
  Edge20,
  Face
};

struct TrianglePoint
{
  Vec3 point;
  Feature feature;
};

inline TrianglePoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return { a, Feature::Vertex0 };
  }
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return { b, Feature::Vertex1 };
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    const double denom = d1 - d3;
    return { denom > 0 ? Vec3(a + (d1 / denom) * ab) : a, Feature::Edge01 };
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return { c, Feature::Vertex2 };
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    const double denom = d2 - d6;
    return { denom > 0 ? Vec3(a + (d2 / denom) * ac) : a, Feature::Edge20 };
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double denom = (d4 - d3) + (d5 - d6);
    return { denom > 0 ? Vec3(b + ((d4 - d3) / denom) * (c - b)) : b, Feature::Edge12 };
  }
  const double sum = va + vb + vc;
  if (!(sum > 0))
  {
    // Degenerate (collinear) triangle that slipped through the tests above: nearest corner.
    const double da = ap.squaredNorm(), db = bp.squaredNorm(), dc = cp.squaredNorm();
    if (da <= db && da <= dc)
    {
      return { a, Feature::Vertex0 };
    }
    return db <= dc ? TrianglePoint{ b, Feature::Vertex1 } : TrianglePoint{ c, Feature::Vertex2 };
  }
  const double v = vb / sum, w = vc / sum;
  return { a + v * ab + w * ac, Feature::Face };
}

} // namespace shrinkwrap

#endif
