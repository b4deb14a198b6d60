#include "Surface/MeshQuality.h"

#include "Surface/SurfaceGeometry.h"

#include <cmath>
#include <limits>

namespace shrinkwrap
{

TriangleQuality triangleQuality(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const auto angles = triangleAngles(a, b, c);
  const Vec3 e1 = b - a, e2 = c - a;
  const double twiceArea = e1.cross(e2).norm(); // |det A| in the triangle's plane
  const double kappa = twiceArea > 0 ? (e1.squaredNorm() + e2.squaredNorm()) / (2 * twiceArea)
                                     : std::numeric_limits<double>::infinity();
  const double toDegrees = 180.0 / M_PI;
  return { toDegrees * std::min({ angles[0], angles[1], angles[2] }),
    toDegrees * std::max({ angles[0], angles[1], angles[2] }), kappa };
}

} // namespace shrinkwrap
