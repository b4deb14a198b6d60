#include "Remeshing/Relaxation.h"

#include "Surface/SurfaceGeometry.h"

namespace shrinkwrap
{

namespace
{
// One Jacobi sweep: every vertex towards the mean of its neighbours, without the normal component.
std::vector<Vec3> smoothTangentially(
  const SurfaceMesh& mesh, const std::vector<Vec3>& x, double weight)
{
  SurfaceGeometry g;
  computeGeometry(mesh, x, g);
  std::vector<Vec3> moved(x);
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    Vec3 centroid = Vec3::Zero();
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      centroid += x[mesh.ring(p)];
    }
    const Vec3 step = centroid / mesh.valence(i) - x[i];
    const Vec3& n = g.normal[i];
    moved[i] += weight * (step - step.dot(n) * n);
  }
  return moved;
}
} // namespace

void relaxTangentially(
  SurfaceMesh& mesh, const RelaxSettings& settings, const std::function<bool()>& stop)
{
  for (int k = 0; k < settings.iterations && !(stop && stop()); ++k)
  {
    mesh.points() = smoothTangentially(mesh, mesh.points(), settings.weight);
    flipEdges(mesh, settings.flips, stop);
  }
}

} // namespace shrinkwrap
