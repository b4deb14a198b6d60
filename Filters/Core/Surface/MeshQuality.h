// Triangle quality as the paper reports it (Section 4.3): minimum and maximum angle, and the
// condition number of the Jacobian of the map from the unit right triangle (0,0), (1,0), (0,1) to
// the triangle's planar representation (Knupp [7]): kappa = |A|_F |A^-1|_F / 2 = (|e1|^2 + |e2|^2)
// / (2 |det A|) with A = [e1 e2] the edges from the first vertex. 1 for an isosceles right
// triangle, infinite if degenerate.
#ifndef ShrinkWrap_MeshQuality_h
#define ShrinkWrap_MeshQuality_h

#include "Common/Box.h"

namespace shrinkwrap
{

struct TriangleQuality
{
  double minAngle; // degrees
  double maxAngle; // degrees
  double jacobianCondition;
};

TriangleQuality triangleQuality(const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace shrinkwrap

#endif
