// The finite-volume quantities of one step (paper Section 2.2, Fig. 5), from the current positions:
// barycentric co-volume areas |V_i| (a third of each incident triangle), angle-weighted outward
// unit normals N_i, cotangent weights w_ij = (cot alpha_ij + cot beta_ij) / 2 per one-ring entry,
// and the mean-curvature vectors h_i = (1/|V_i|) sum_j w_ij (F_j - F_i) (the discrete
// Laplace-Beltrami of F).
#ifndef ShrinkWrap_SurfaceGeometry_h
#define ShrinkWrap_SurfaceGeometry_h

#include "Surface/SurfaceMesh.h"

#include <cmath>
#include <vector>

namespace shrinkwrap
{

struct SurfaceGeometry
{
  std::vector<double> triangleArea;
  std::vector<double> coVolume; // |V_i|
  std::vector<Vec3> normal;     // N_i
  std::vector<double> weight;   // w_ij, indexed like the one-rings
  std::vector<Vec3> curvature;  // h_i
  double area = 0;              // total
};

void computeGeometry(const SurfaceMesh& mesh, const std::vector<Vec3>& points, SurfaceGeometry& g);

// Angles of triangle (a, b, c) at a, b and c.
std::array<double, 3> triangleAngles(const Vec3& a, const Vec3& b, const Vec3& c);

// The smallest angle of a triangle (radians): the one opposite its shortest edge, one atan2.
double smallestAngle(const Vec3& a, const Vec3& b, const Vec3& c);

// Whether that angle is below `angle`: the smallest angle's sine first, whose bound settles all
// but the triangles within a hair of it without an atan2 (the hold-back asks it of every triangle).
bool smallestAngleBelow(const Vec3& a, const Vec3& b, const Vec3& c, double angle);

struct SmallestAngle
{
  double angle = M_PI; // radians
  int triangle = -1;
};
// The smallest triangle angle of the surface, and where (in parallel).
SmallestAngle smallestAngle(const SurfaceMesh& mesh, const std::vector<Vec3>& points);

// Volume enclosed by a closed surface: positive when it is outward oriented.
double enclosedVolume(const SurfaceMesh& mesh, const std::vector<Vec3>& points);

} // namespace shrinkwrap

#endif
