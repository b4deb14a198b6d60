// The evolver (besides the shrinking-sphere tables): redistribution does its job, advection onto a
// target, failures reported, scale covariance, the domain, refused settings, and vertices that land
// off the target by their edges' sagitta (EvolverSettings::facetFit).
#include "Distance/DistanceSource.h"
#include "Distance/SignedDistance.h"
#include "Evolution/Evolver.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include <vtkSMPTools.h>

namespace
{
using namespace shrinkwrap;
using testing::meshOf;

struct Shape
{
  double coVolumeRatio;
  double minAngleDegrees;     // the worst triangle
  double meanMinAngleDegrees; // the smallest angle of each triangle, averaged
};

// An ellipsoid evolving by mean curvature flow for `steps` steps.
Shape ellipsoidFlow(Redistribution redistribution, int steps)
{
  TriangleSoup ellipsoid = icosphere(3);
  for (Vec3& p : ellipsoid.points)
  {
    p = p.cwiseProduct(Vec3(1.0, 0.5, 0.35));
  }
  const SurfaceMesh mesh = meshOf(ellipsoid);
  EvolverSettings settings = EvolverSettings::paper();
  settings.C1 = 1;
  settings.C2 = 0;
  settings.C = 0;
  settings.timeStep = 1e-4;
  settings.redistribution = redistribution;
  settings.omegaAngle = 1.0;
  settings.omegaVolume = 1.0;
  Evolver evolver(mesh, settings);
  for (int k = 0; k < steps; ++k)
  {
    const StepReport r = evolver.step();
    SW_CHECK(r.ok(), "ellipsoid flow step " << k << ": " << r.message);
    if (!r.ok())
    {
      break;
    }
  }
  const SurfaceGeometry g = evolver.geometry();
  const auto [lo, hi] = std::minmax_element(g.coVolume.begin(), g.coVolume.end());
  const std::vector<Vec3> x = evolver.positions();
  double meanMin = 0;
  for (const auto& t : mesh.triangles())
  {
    const auto a = triangleAngles(x[t[0]], x[t[1]], x[t[2]]);
    meanMin += std::min({ a[0], a[1], a[2] });
  }
  meanMin /= mesh.triangleCount();
  return { *hi / *lo, smallestAngle(mesh, x).angle * 180 / M_PI, meanMin * 180 / M_PI };
}

void redistributionDoesItsJob()
{
  const int steps = 300;
  const Shape none = ellipsoidFlow(Redistribution::None, steps);
  const Shape volume = ellipsoidFlow(Redistribution::Volume, steps);
  const Shape angle = ellipsoidFlow(Redistribution::Angle, steps);
  std::printf(
    "ellipsoid (1, 0.5, 0.35) from an icosphere of level 3, MCF, %d steps of 1e-4, omega 1:\n",
    steps);
  for (const auto& [name, shape] : { std::make_pair("none", none), std::make_pair("volume", volume),
         std::make_pair("angle", angle) })
  {
    std::printf("  %-7s max/min co-volume %7.2f, min angle %5.2f deg, mean of triangles' min "
                "angles %5.2f deg\n",
      name, shape.coVolumeRatio, shape.minAngleDegrees, shape.meanMinAngleDegrees);
  }
  SW_CHECK((none.coVolumeRatio - 1) >= 3 * (volume.coVolumeRatio - 1),
    "volume-based redistribution evens co-volumes at least 3x better than none");
  SW_CHECK(angle.minAngleDegrees > none.minAngleDegrees &&
      angle.meanMinAngleDegrees > none.meanMinAngleDegrees,
    "angle-based redistribution (omega_angle = 1) keeps the minimum angles higher");
}

void advection()
{
  // The signed distance of a unit sphere, from the project's own SDF (the lattice the filter
  // writes).
  const TriangleSoup target = icosphere(5);
  TriangleSoup soup{ target.points, target.triangles };
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.6, 64, 0 }, lattice);
  std::vector<float> values(lattice.nodeCount());
  computeSignedDistance(soup, lattice, {}, values.data());
  const DistanceGrid field(lattice, values);
  const double h = lattice.spacing.x();

  // A sphere of radius 2 moved by advection (C > 0) with little diffusion (C1 small).
  const SurfaceMesh start = meshOf(icosphere(3, Vec3::Zero(), 2.0));
  EvolverSettings settings = EvolverSettings::paper();
  settings.timeStep = 0.02;
  settings.C1 = 0.05;
  settings.C2 = 1.0;
  settings.C = 5.0;
  settings.D = 0.0;
  const TargetDistance distance(field);
  Evolver evolver(start, settings, &distance, lattice.bounds());
  for (int k = 0; k < 200; ++k)
  {
    const StepReport r = evolver.step();
    SW_CHECK(r.ok(), "advection step: " << r.message);
    if (!r.ok())
    {
      break;
    }
  }
  double worst = 0;
  for (const Vec3& x : evolver.positions())
  {
    worst = std::max(worst, std::abs(x.norm() - 1.0));
  }
  std::printf(
    "advection: radius 2 -> max | |x| - 1 | = %.4f = %.3f h after 200 steps\n", worst, worst / h);
  SW_CHECK(worst <= 0.5 * h, "the sphere settles on the unit sphere within 0.5 h");
}

void failureIsReported()
{
  const SurfaceMesh mesh = meshOf(icosphere(3));
  EvolverSettings settings = EvolverSettings::paper();
  settings.C2 = 0;
  settings.C = 0;
  settings.timeStep = 0.3; // r(t)^2 = 1 - 4t: the sphere vanishes at t = 0.25
  Box domain;
  domain.extend(Vec3::Constant(-2));
  domain.extend(Vec3::Constant(2));
  Evolver evolver(mesh, settings, nullptr, domain);
  int reports = 0;
  const StepReport r = evolver.run(20, Progress([&](double) { return ++reports > 0; }));
  std::printf("too large a step: %s\n", r.message.c_str());
  SW_CHECK(!r.ok() && r.step >= 1 && r.step <= 20 && r.where >= 0 && !r.message.empty(),
    "the failure is reported with its step and place");
  bool finite = true;
  for (const Vec3& x : evolver.positions())
  {
    finite = finite && x.allFinite();
  }
  SW_CHECK(
    finite && evolver.steps() == r.step - 1, "the last good surface is kept: no NaN escapes");
  SW_CHECK(reports == r.step - 1,
    "run() reported progress after each good step and stopped at the failure");
}

void scaledEvolution()
{
  // Mean curvature flow is scale covariant (y = phi x, t' = phi^2 t): evolving scaled coordinates
  // with tau' = phi^2 tau gives the same surface, and the caller sees it in its own units. (The
  // redistribution terms and eta are not covariant: omega_vol (A/N_V - |V_i|) and the angle
  // velocity carry lengths, so the scale of Section 2.4 changes their effective weights, as the
  // paper's stability study shows.)
  const SurfaceMesh mesh = meshOf(icosphere(3, Vec3(0.5, -1, 2), 1.5));
  EvolverSettings settings = EvolverSettings::paper();
  settings.C2 = 0;
  settings.C = 0;
  settings.solverTolerance = 1e-13;
  settings.timeStep = 0.002;
  Evolver plain(mesh, settings);
  const double phi = 3.7;
  settings.timeStep *= phi * phi;
  Evolver scaled(mesh, settings, nullptr, Box(), phi, Vec3(0.5, -1, 2));
  for (int k = 0; k < 20; ++k)
  {
    plain.step();
    scaled.step();
  }
  double worst = 0;
  const auto a = plain.positions(), b = scaled.positions();
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    worst = std::max(worst, (a[i] - b[i]).norm());
  }
  SW_CHECK(worst < 1e-8 && std::abs(plain.time() - scaled.time()) < 1e-12,
    "scaled evolution matches in the caller's units (" << worst << ")");
}

void leavingTheDomain()
{
  const SurfaceMesh mesh = meshOf(icosphere(2));
  EvolverSettings settings = EvolverSettings::paper();
  settings.C2 = 0;
  settings.C = 0;
  Box domain;
  domain.extend(Vec3::Constant(-0.5));
  domain.extend(Vec3::Constant(0.5));
  Evolver evolver(mesh, settings, nullptr, domain);
  const StepReport r = evolver.step();
  SW_CHECK(r.failure == Failure::LeftDomain && r.step == 1 && r.where >= 0,
    "leaving the domain is reported: " << r.message);
}

void refusedSettings()
{
  const TriangleSoup tet{ { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } } };
  const SurfaceMesh mesh = meshOf(tet);
  for (const auto& [what, change] :
    std::vector<std::pair<std::string, std::function<void(EvolverSettings&)>>>{
      { "tau = 0", [](EvolverSettings& s) { s.timeStep = 0; } },
      { "tau < 0", [](EvolverSettings& s) { s.timeStep = -0.1; } },
      { "C1 < 0", [](EvolverSettings& s) { s.C1 = -1; } },
      { "C < 0", [](EvolverSettings& s) { s.C = -1; } },
      { "D < 0", [](EvolverSettings& s) { s.D = -1; } },
      { "omega < 0", [](EvolverSettings& s) { s.omegaAngle = -1; } } })
  {
    EvolverSettings settings;
    change(settings);
    const Evolver evolver(mesh, settings);
    SW_CHECK(!evolver.status(), what << " refused: " << evolver.status().message());
  }
}

// A unit sphere wrapped with remeshing to edges of 0.3 (a sagitta of 0.3^2 / 8 = 0.011), its near
// field exact (the target a fine icosphere: its own facets cut in by 0.0005): the wrap's vertices,
// and points spread over its triangles, against the sphere.
struct Landing
{
  double vertexOffset;  // mean |x| - 1 over the vertices
  double facetDistance; // mean | |p| - 1 | over points spread over the triangles
  double sagitta;       // l^2 / 8 of the mean edge l
};
Landing landOnSphere(double facetFit)
{
  const TriangleSoup target = icosphere(6);
  const TriangleSoup soup{ target.points, target.triangles };
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.6, 48, 0 }, lattice);
  std::vector<float> values(lattice.nodeCount());
  computeSignedDistance(soup, lattice, {}, values.data());
  const TargetDistance distance(
    DistanceGrid(lattice, values), std::make_shared<const TriangleSource>(soup));
  EvolverSettings settings;
  settings.facetFit = facetFit;
  RemeshSettings remeshing = EvolverSettings::duringEvolution();
  remeshing.targetLength = 0.3;
  settings.remeshing = remeshing;
  Evolver evolver(meshOf(icosphere(3, Vec3::Zero(), 1.2)), settings, &distance, lattice.bounds());
  for (int k = 0; k < 40; ++k)
  {
    const StepReport r = evolver.step();
    SW_CHECK(r.ok(), "landing step: " << r.message);
    if (!r.ok())
    {
      break;
    }
  }
  const std::vector<Vec3> x = evolver.positions();
  Landing l{ 0, 0, 0 };
  for (const Vec3& p : x)
  {
    l.vertexOffset += (p.norm() - 1) / x.size();
  }
  double edges = 0, length = 0;
  int samples = 0;
  for (const auto& t : evolver.mesh().triangles())
  {
    for (int k = 0; k < 3; ++k)
    {
      length += (x[t[k]] - x[t[(k + 1) % 3]]).norm();
      ++edges;
    }
    for (int a = 0; a <= 4; ++a) // barycentric points on a grid of step 1/4
    {
      for (int b = 0; a + b <= 4; ++b)
      {
        const Vec3 p = (a * x[t[0]] + b * x[t[1]] + (4 - a - b) * x[t[2]]) / 4.0;
        l.facetDistance += std::abs(p.norm() - 1);
        ++samples;
      }
    }
  }
  l.facetDistance /= samples;
  l.sagitta = std::pow(length / edges, 2) / 8;
  return l;
}

// On the target the wrap's facets cut inside the sphere by about the sagitta; landed a sagitta out,
// they straddle it.
void facetsStraddleTheTarget()
{
  const Landing plain = landOnSphere(0), fitted = landOnSphere(1);
  std::printf("facet fit: vertices at %+.5f (without) / %+.5f (with) of the sphere, edge sagitta "
              "%.5f / %.5f; "
              "mean facet distance %.5f / %.5f\n",
    plain.vertexOffset, fitted.vertexOffset, plain.sagitta, fitted.sagitta, plain.facetDistance,
    fitted.facetDistance);
  SW_CHECK(std::abs(plain.vertexOffset) < 0.1 * plain.sagitta,
    "without the fit, the vertices land on the sphere");
  SW_CHECK(fitted.vertexOffset > 0.5 * fitted.sagitta && fitted.vertexOffset < 1.5 * fitted.sagitta,
    "with it, they land about an edge's sagitta outside");
  SW_CHECK(
    fitted.facetDistance < 0.6 * plain.facetDistance, "and the facets lie closer to the sphere");
}

} // namespace

int TestEvolver(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    redistributionDoesItsJob();
    advection();
    failureIsReported();
    scaledEvolution();
    leavingTheDomain();
    refusedSettings();
    facetsStraddleTheTarget();
  });
  return testing::finish("TestEvolver");
}
