#include "Remeshing/EdgeFlips.h"

#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

namespace
{
Vec3 unitNormal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 ? Vec3(n / length) : Vec3::Zero();
}

} // namespace

bool flipKeepsShape(const std::vector<Vec3>& x, int i, int j, int c, int d, double cosMax)
{
  const Vec3 n1 = unitNormal(x[i], x[j], x[c]), n2 = unitNormal(x[i], x[d], x[j]);
  const Vec3 n3 = unitNormal(x[i], x[d], x[c]), n4 = unitNormal(x[d], x[j], x[c]);
  return !(n1.dot(n2) < cosMax || n3.dot(n4) < cosMax || n3.dot(n1 + n2) <= 0 || n4.dot(n1 + n2) <= 0);
}

bool flipGainsAngle(const std::vector<Vec3>& x, int i, int j, int c, int d, double minGain)
{
  // Only non-Delaunay edges (angles at c and d summing past pi) can gain; this test is cheap.
  const Vec3 ci = x[i] - x[c], cj = x[j] - x[c], di = x[i] - x[d], dj = x[j] - x[d];
  const double sinC = ci.cross(cj).norm(), sinD = di.cross(dj).norm();
  if (ci.dot(cj) * sinD + di.dot(dj) * sinC >= 0) // sin(C + D) >= 0: Delaunay already
  {
    return false;
  }
  const double before = std::min(smallestAngle(x[i], x[j], x[c]), smallestAngle(x[i], x[d], x[j]));
  const double after = std::min(smallestAngle(x[i], x[d], x[c]), smallestAngle(x[d], x[j], x[c]));
  return after >= before + minGain;
}

// Over the edges (i, j), i < j, with triangles (i, j, c) and (i, d, j). The rings describe the
// connectivity before the pass, hence one flip per vertex.
int flipEdges(SurfaceMesh& mesh, const FlipSettings& settings)
{
  const std::vector<Vec3>& x = mesh.points();
  const double cosMax = std::cos(settings.maxDihedral * M_PI / 180.0);
  const std::vector<std::array<int, 3>> triangles = mesh.triangles(); // flips change the mesh's own
  CrossingGuard guard(x, triangles, settings.guardOnlyIn);
  std::vector<char> touched(mesh.vertexCount(), 0);
  int flips = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      const int j = mesh.ring(p);
      const int c = mesh.ring(mesh.next(i, p)), d = mesh.ring(mesh.previous(i, p));
      if (j < i || touched[i] || touched[j] || touched[c] || touched[d] || mesh.valence(i) <= 3 ||
        mesh.valence(j) <= 3 || c == d)
      {
        continue;
      }
      // (c, d) already an edge: the flip would pinch the surface.
      if (!flipGainsAngle(x, i, j, c, d, settings.minGain) || mesh.ringEntry(c, d) >= 0)
      {
        continue;
      }
      if (!flipKeepsShape(x, i, j, c, d, cosMax) || (settings.avoidCrossings && guard.flipCrosses(i, j, c, d)))
      {
        continue;
      }
      if (mesh.flip(i, j))
      {
        touched[i] = touched[j] = touched[c] = touched[d] = 1;
        ++flips;
        if (settings.avoidCrossings)
        {
          guard.addFlip(i, j, c, d);
        }
      }
    }
  }
  return mesh.commit() ? flips : 0;
}

} // namespace shrinkwrap
