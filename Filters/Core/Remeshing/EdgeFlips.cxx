#include "Remeshing/EdgeFlips.h"

#include "Common/Progress.h"
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
  return !(
    n1.dot(n2) < cosMax || n3.dot(n4) < cosMax || n3.dot(n1 + n2) <= 0 || n4.dot(n1 + n2) <= 0);
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

FlipPass::FlipPass(const SurfaceMesh& mesh, const FlipSettings& settings)
  : Settings(settings)
  , X(mesh.points())
  , CosMax(std::cos(settings.maxDihedral * M_PI / 180.0))
  , Triangles(mesh.triangles())
  , Guard(X, Triangles, settings.guardOnlyIn)
  , Touched(mesh.vertexCount(), 0)
{
}

bool FlipPass::free(const SurfaceMesh& mesh, int i, int j, int c, int d) const
{
  const std::vector<char>& t = this->Touched;
  return !(t[i] || t[j] || t[c] || t[d] || mesh.valence(i) <= 3 || mesh.valence(j) <= 3 || c == d);
}

bool FlipPass::flip(SurfaceMesh& mesh, int i, int j, int c, int d)
{
  const bool guarded = this->Settings.avoidCrossings;
  if (!flipKeepsShape(this->X, i, j, c, d, this->CosMax) ||
    (guarded && this->Guard.flipCrosses(i, j, c, d)) || !mesh.flip(i, j))
  {
    return false;
  }
  this->Touched[i] = this->Touched[j] = this->Touched[c] = this->Touched[d] = 1;
  ++this->Flips;
  if (guarded)
  {
    this->Guard.addFlip(i, j, c, d);
  }
  return true;
}

// Over the edges (i, j), i < j, with triangles (i, j, c) and (i, d, j).
int flipEdges(SurfaceMesh& mesh, const FlipSettings& settings, const std::function<bool()>& stop)
{
  FlipPass pass(mesh, settings);
  StopPoll stopped(stop);
  pass.setStop([&] { return stopped.now(); });
  for (int i = 0; i < mesh.vertexCount() && !stopped(); ++i)
  {
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      const int j = mesh.ring(p);
      const int c = mesh.ring(mesh.next(i, p)), d = mesh.ring(mesh.previous(i, p));
      // (c, d) already an edge: the flip would pinch the surface.
      if (j > i && pass.free(mesh, i, j, c, d) &&
        flipGainsAngle(pass.points(), i, j, c, d, settings.minGain) && mesh.ringEntry(c, d) < 0)
      {
        pass.flip(mesh, i, j, c, d);
      }
    }
  }
  return mesh.commit() ? pass.flips() : 0;
}

} // namespace shrinkwrap
