// The stability scale of Section 2.4: the square root, not eq. (7)'s cube root, brings the mean
// co-volume to tau.
#include "Evolution/StabilityScaling.h"
#include "Surface/Icosphere.h"
#include "Surface/SurfaceGeometry.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

namespace
{
using namespace shrinkwrap;
using testing::meshOf;

void stabilityScaling()
{
  // Eq. (7) prints phi = cbrt(tau / mu_r); areas scale with phi^2, so only the square root brings
  // the mean co-volume to tau. Measured on an icosphere of radius r scaled by phi.
  const double tau = 0.015, r = 10.0; // tau / mu_r far from 1, where the roots differ
  const int level = 3;
  const SurfaceMesh mesh = meshOf(icosphere(level, Vec3::Zero(), r));
  for (const bool squareRoot : { true, false })
  {
    const double phi =
      squareRoot ? stabilityScale(tau, r, level) : std::cbrt(tau / meanCoVolume(r, level));
    std::vector<Vec3> scaled;
    for (const Vec3& x : mesh.points())
    {
      scaled.push_back(phi * x);
    }
    SurfaceGeometry g;
    computeGeometry(mesh, scaled, g);
    const double mean = g.area / mesh.vertexCount();
    std::printf("phi by %s: mean co-volume %.5f for tau %.5f\n",
      squareRoot ? "sqrt (ours)" : "cbrt (eq. (7))", mean, tau);
    if (squareRoot)
    {
      SW_CHECK(
        std::abs(mean - tau) < 0.05 * tau, "phi = sqrt(tau / mu_r) gives mean co-volume tau");
    }
    else
    {
      SW_CHECK(std::abs(mean - tau) > 0.5 * tau, "eq. (7)'s cube root does not");
    }
  }
}

} // namespace

int TestStabilityScaling(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] { stabilityScaling(); });
  return testing::finish("TestStabilityScaling");
}
