// Closest point on a triangle, with the feature (vertex, edge or face) it lies on.
// Ericson, Real-Time Collision Detection, 5.1.5: Voronoi regions tested in order, no square roots.
// The feature picks the angle-weighted pseudonormal that signs band nodes (Baerentzen & Aanaes
// 2005).
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

namespace detail
{
// Ericson's tests at corner q of a triangle with corner a, edge e = q - a and other edge f from a:
// p's offset from q projected on e and f, whether p lies in q's vertex region, and the barycentric
// numerator v that, with those projections at a (ea, fa), says whether it lies in edge e's region.
struct Corner
{
  double e, f, v;
  bool vertex, edge;
};

inline Corner corner(const Vec3& e, const Vec3& f, const Vec3& qp, double ea, double fa)
{
  Corner c;
  c.e = e.dot(qp);
  c.f = f.dot(qp);
  c.vertex = c.e >= 0 && c.f <= c.e;
  c.v = ea * c.f - c.e * fa;
  c.edge = c.v <= 0 && ea >= 0 && c.e <= 0;
  return c;
}

// The point t / length of the way along `edge` from `from` (from itself on a degenerate edge).
inline Vec3 alongEdge(const Vec3& from, const Vec3& edge, double t, double length)
{
  return length > 0 ? Vec3(from + (t / length) * edge) : from;
}
} // namespace detail

inline TrianglePoint closestPointOnTriangle(
  const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return { a, Feature::Vertex0 };
  }
  const detail::Corner atB = detail::corner(ab, ac, p - b, d1, d2); // d3, d4 and vc of Ericson's
  if (atB.vertex)
  {
    return { b, Feature::Vertex1 };
  }
  if (atB.edge)
  {
    return { detail::alongEdge(a, ab, d1, d1 - atB.e), Feature::Edge01 };
  }
  const detail::Corner atC = detail::corner(ac, ab, p - c, d2, d1); // d6, d5 and vb
  if (atC.vertex)
  {
    return { c, Feature::Vertex2 };
  }
  if (atC.edge)
  {
    return { detail::alongEdge(a, ac, d2, d2 - atC.e), Feature::Edge20 };
  }
  const double va = atB.e * atC.e - atC.f * atB.f;
  const double toB = atB.f - atB.e, toC = atC.f - atC.e; // d4 - d3, d5 - d6
  if (va <= 0 && toB >= 0 && toC >= 0)
  {
    return { detail::alongEdge(b, c - b, toB, toB + toC), Feature::Edge12 };
  }
  const double sum = va + atC.v + atB.v;
  if (!(sum > 0))
  {
    // Degenerate (collinear) triangle that slipped through the tests above: nearest corner.
    const double da = ap.squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    if (da <= db && da <= dc)
    {
      return { a, Feature::Vertex0 };
    }
    return db <= dc ? TrianglePoint{ b, Feature::Vertex1 } : TrianglePoint{ c, Feature::Vertex2 };
  }
  const double v = atC.v / sum, w = atB.v / sum;
  return { a + v * ab + w * ac, Feature::Face };
}

} // namespace shrinkwrap

#endif
