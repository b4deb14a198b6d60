// Points and vectors in double precision, and the geometric primitives everything else builds on.
#ifndef ShrinkWrap_Vec3_h
#define ShrinkWrap_Vec3_h

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <cmath>

namespace shrinkwrap
{

using Vec3 = Eigen::Vector3d;

// The angle between u and v, one atan2: accurate at every angle, unlike acos near 0 and pi.
inline double angleBetween(const Vec3& u, const Vec3& v)
{
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// Six times the signed volume of the tetrahedron (origin, a, b, c): summed over the triangles of a
// closed, outward oriented surface, six times the volume it encloses.
inline double tripleProduct(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return a.dot(b.cross(c));
}

} // namespace shrinkwrap

#endif
