// The evolver's building blocks and bars of issue #3 besides the shrinking-sphere tables: icosphere and
// one-rings, distance sampling, the stability scale of Section 2.4, that redistribution does its job,
// advection onto a target, failure detection, edge flips, and bad input.
#include "DistanceGrid.h"
#include "EdgeCollapses.h"
#include "EdgeFlips.h"
#include "Evolver.h"
#include "Icosphere.h"
#include "SignedDistance.h"
#include "StabilityScaling.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <functional>
#include <random>

namespace
{
using namespace shrinkwrap;

SurfaceMesh meshOf(const TriangleSurface& surface)
{
  SurfaceMesh mesh;
  std::string error;
  SW_CHECK(SurfaceMesh::build(surface.points, surface.triangles, mesh, error), "surface builds: " << error);
  return mesh;
}

void icospheres()
{
  const long long expected[7] = { 12, 42, 162, 642, 2562, 10242, 40962 };
  for (int s = 0; s <= 6; ++s)
  {
    const TriangleSurface sphere = icosphere(s, Vec3(1, 2, 3), 2.0);
    SW_CHECK(static_cast<long long>(sphere.points.size()) == expected[s] && icosphereVertexCount(s) == expected[s],
      "icosphere level " << s << " has " << expected[s] << " vertices (eq. (9))");
    if (s > 4)
    {
      continue;
    }
    const SurfaceMesh mesh = meshOf(sphere);
    int ringEntries = 0;
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      ringEntries += mesh.valence(i);
      // Counter-clockwise rings: consecutive neighbours j, k make triangle (i, j, k) of the mesh.
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const auto& t = mesh.triangles()[mesh.ringTriangle(p)];
        const int j = mesh.ring(p), k = mesh.ring(mesh.next(i, p));
        const bool matches = (t[0] == i && t[1] == j && t[2] == k) || (t[1] == i && t[2] == j && t[0] == k) ||
          (t[2] == i && t[0] == j && t[1] == k);
        SW_CHECK(matches, "ring entry " << p << " of vertex " << i << " names its triangle");
      }
    }
    SW_CHECK(ringEntries == 3 * mesh.triangleCount(), "ring entries = 2 E = 3 T on level " << s);
    const double volume = enclosedVolume(mesh, sphere.points);
    SW_CHECK(volume > 0 && volume < 4.0 / 3.0 * M_PI * 8.0, "outward orientation, inscribed volume on level " << s);
  }
}

void distanceSampling()
{
  // A linear function is reproduced exactly by trilinear interpolation, and so is its gradient.
  GridLattice lattice;
  lattice.origin = Vec3(-1, -2, 0.5);
  lattice.spacing = Vec3(0.1, 0.2, 0.15);
  lattice.dims = { 21, 17, 13 };
  const Vec3 a(0.3, -1.2, 2.0);
  std::vector<float> values(lattice.nodeCount());
  for (int k = 0; k < lattice.dims[2]; ++k)
    for (int j = 0; j < lattice.dims[1]; ++j)
      for (int i = 0; i < lattice.dims[0]; ++i)
        values[lattice.index(i, j, k)] = static_cast<float>(a.dot(lattice.position(i, j, k)) + 0.7);
  const DistanceGrid grid(lattice, values);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0, worstGradient = 0;
  const Box box = lattice.bounds();
  for (int n = 0; n < 1000; ++n)
  {
    const Vec3 x = box.min + Vec3(u(random), u(random), u(random)).cwiseProduct(box.size());
    const DistanceSample s = grid.sample(x);
    worst = std::max(worst, std::abs(s.value - (a.dot(x) + 0.7)));
    worstGradient = std::max(worstGradient, (s.gradient - a).norm());
  }
  SW_CHECK(worst < 1e-5 && worstGradient < 1e-4, "trilinear value and gradient exact for a linear field ("
      << worst << ", " << worstGradient << ")");
}

void stabilityScaling()
{
  // Eq. (7) prints phi = cbrt(tau / mu_r); areas scale with phi^2, so only the square root brings the
  // mean co-volume to tau. Measured on an icosphere of radius r scaled by phi.
  const double tau = 0.015, r = 10.0; // tau / mu_r far from 1, where the roots differ
  const int level = 3;
  const SurfaceMesh mesh = meshOf(icosphere(level, Vec3::Zero(), r));
  for (const bool squareRoot : { true, false })
  {
    const double phi = squareRoot ? stabilityScale(tau, r, level) : std::cbrt(tau / meanCoVolume(r, level));
    std::vector<Vec3> scaled;
    for (const Vec3& x : mesh.initialPoints())
    {
      scaled.push_back(phi * x);
    }
    SurfaceGeometry g;
    computeGeometry(mesh, scaled, g);
    const double mean = g.area / mesh.vertexCount();
    std::printf("phi by %s: mean co-volume %.5f for tau %.5f\n", squareRoot ? "sqrt (ours)" : "cbrt (eq. (7))", mean, tau);
    if (squareRoot)
    {
      SW_CHECK(std::abs(mean - tau) < 0.05 * tau, "phi = sqrt(tau / mu_r) gives mean co-volume tau");
    }
    else
    {
      SW_CHECK(std::abs(mean - tau) > 0.5 * tau, "eq. (7)'s cube root does not");
    }
  }
}

struct Shape
{
  double coVolumeRatio;
  double minAngleDegrees;     // the worst triangle
  double meanMinAngleDegrees; // the smallest angle of each triangle, averaged
};

// An ellipsoid evolving by mean curvature flow for `steps` steps.
Shape ellipsoidFlow(Redistribution redistribution, int steps)
{
  TriangleSurface ellipsoid = icosphere(3);
  for (Vec3& p : ellipsoid.points)
  {
    p = p.cwiseProduct(Vec3(1.0, 0.5, 0.35));
  }
  const SurfaceMesh mesh = meshOf(ellipsoid);
  EvolverSettings settings;
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
  std::printf("ellipsoid (1, 0.5, 0.35) from an icosphere of level 3, MCF, %d steps of 1e-4, omega 1:\n", steps);
  for (const auto& [name, shape] : { std::make_pair("none", none), std::make_pair("volume", volume),
         std::make_pair("angle", angle) })
  {
    std::printf("  %-7s max/min co-volume %7.2f, min angle %5.2f deg, mean of triangles' min angles %5.2f deg\n",
      name, shape.coVolumeRatio, shape.minAngleDegrees, shape.meanMinAngleDegrees);
  }
  SW_CHECK((none.coVolumeRatio - 1) >= 3 * (volume.coVolumeRatio - 1),
    "volume-based redistribution evens co-volumes at least 3x better than none");
  SW_CHECK(angle.minAngleDegrees > none.minAngleDegrees && angle.meanMinAngleDegrees > none.meanMinAngleDegrees,
    "angle-based redistribution (omega_angle = 1) keeps the minimum angles higher");
}

void advection()
{
  // The signed distance of a unit sphere, from the project's own SDF (the lattice the filter writes).
  const TriangleSurface target = icosphere(5);
  TriangleSoup soup{ target.points, target.triangles };
  GridLattice lattice;
  std::string error;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.6, 64, 0 }, lattice, error);
  std::vector<float> values(lattice.nodeCount());
  computeSignedDistance(soup, lattice, {}, values.data());
  const DistanceGrid field(lattice, values);
  const double h = lattice.spacing.x();

  // A sphere of radius 2 moved by advection (C > 0) with little diffusion (C1 small).
  const SurfaceMesh start = meshOf(icosphere(3, Vec3::Zero(), 2.0));
  EvolverSettings settings;
  settings.timeStep = 0.02;
  settings.C1 = 0.05;
  settings.C2 = 1.0;
  settings.C = 5.0;
  settings.D = 0.0;
  Evolver evolver(start, settings, &field, lattice.bounds());
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
  std::printf("advection: radius 2 -> max | |x| - 1 | = %.4f = %.3f h after 200 steps\n", worst, worst / h);
  SW_CHECK(worst <= 0.5 * h, "the sphere settles on the unit sphere within 0.5 h");
}

void failureIsReported()
{
  const SurfaceMesh mesh = meshOf(icosphere(3));
  EvolverSettings settings;
  settings.C2 = 0;
  settings.C = 0;
  settings.timeStep = 0.3; // r(t)^2 = 1 - 4t: the sphere vanishes at t = 0.25
  Box domain;
  domain.extend(Vec3::Constant(-2));
  domain.extend(Vec3::Constant(2));
  Evolver evolver(mesh, settings, nullptr, domain);
  StepReport r;
  int k = 0;
  for (; k < 20 && r.ok(); ++k)
  {
    r = evolver.step();
  }
  std::printf("too large a step: %s\n", r.message.c_str());
  SW_CHECK(!r.ok() && r.step >= 1 && r.step <= 20 && r.where >= 0 && !r.message.empty(),
    "the failure is reported with its step and place");
  bool finite = true;
  for (const Vec3& x : evolver.positions())
  {
    finite = finite && x.allFinite();
  }
  SW_CHECK(finite && evolver.steps() == r.step - 1, "the last good surface is kept: no NaN escapes");
}

void scaledEvolution()
{
  // Mean curvature flow is scale covariant (y = phi x, t' = phi^2 t): evolving scaled coordinates with
  // tau' = phi^2 tau gives the same surface, and the caller sees it in its own units. (The redistribution
  // terms and eta are not covariant: omega_vol (A/N_V - |V_i|) and the angle velocity carry lengths, so
  // the scale of Section 2.4 changes their effective weights, as the paper's stability study shows.)
  const SurfaceMesh mesh = meshOf(icosphere(3, Vec3(0.5, -1, 2), 1.5));
  EvolverSettings settings;
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
  EvolverSettings settings;
  settings.C2 = 0;
  settings.C = 0;
  Box domain;
  domain.extend(Vec3::Constant(-0.5));
  domain.extend(Vec3::Constant(0.5));
  Evolver evolver(mesh, settings, nullptr, domain);
  const StepReport r = evolver.step();
  SW_CHECK(r.failure == Failure::LeftDomain && r.step == 1 && r.where >= 0, "leaving the domain is reported: " << r.message);
}

void badInput()
{
  SurfaceMesh mesh;
  std::string error;
  const TriangleSurface tet{ { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } } };
  SW_CHECK(SurfaceMesh::build(tet.points, tet.triangles, mesh, error), "a tetrahedron is a closed surface");
  SW_CHECK(!SurfaceMesh::build({}, {}, mesh, error), "empty surface refused: " << error);
  TriangleSurface isolated = tet;
  isolated.points.push_back({ 5, 5, 5 });
  SW_CHECK(!SurfaceMesh::build(isolated.points, isolated.triangles, mesh, error), "isolated vertex refused: " << error);
  TriangleSurface open = tet;
  open.triangles.pop_back();
  SW_CHECK(!SurfaceMesh::build(open.points, open.triangles, mesh, error), "open surface refused: " << error);
  TriangleSurface fin = tet; // a third triangle on edge (0, 1)
  fin.points.push_back({ 0.5, -1, 0 });
  fin.triangles.push_back({ 0, 1, 4 });
  SW_CHECK(!SurfaceMesh::build(fin.points, fin.triangles, mesh, error), "non-manifold edge refused: " << error);
  TriangleSurface flipped = tet;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  SW_CHECK(!SurfaceMesh::build(flipped.points, flipped.triangles, mesh, error), "inconsistent orientation refused: " << error);
  TriangleSurface nan = tet;
  nan.points[1].x() = std::nan("");
  SW_CHECK(!SurfaceMesh::build(nan.points, nan.triangles, mesh, error), "NaN refused: " << error);

  SurfaceMesh::build(tet.points, tet.triangles, mesh, error);
  for (const auto& [what, change] : std::vector<std::pair<std::string, std::function<void(EvolverSettings&)>>>{
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
    SW_CHECK(!evolver.error().empty(), what << " refused: " << evolver.error());
  }
}

// Share of triangles with an angle below 20 degrees.
double thinShare(const std::vector<std::array<int, 3>>& triangles, const std::vector<Vec3>& x)
{
  int thin = 0;
  for (const auto& t : triangles)
  {
    thin += smallestAngle(x[t[0]], x[t[1]], x[t[2]]) < 20 * M_PI / 180;
  }
  return static_cast<double>(thin) / triangles.size();
}

void edgeFlips()
{
  // An icosphere stretched 4 times along x: thin triangles everywhere, on a smooth convex shape.
  TriangleSurface stretched = icosphere(3, Vec3::Zero(), 1.0);
  for (Vec3& p : stretched.points)
  {
    p.x() *= 4;
  }
  const SurfaceMesh mesh = meshOf(stretched);
  const std::vector<Vec3>& x = stretched.points;
  // Four passes, each on the triangles of the one before.
  std::vector<std::array<int, 3>> flipped;
  FlipSettings settings;
  SurfaceMesh after = mesh;
  std::string error;
  bool closed = true;
  int flips = 0;
  for (int pass = 0; pass < 4 && closed; ++pass)
  {
    flips += flipEdges(after, x, settings, flipped);
    closed = SurfaceMesh::build(x, flipped, after, error);
  }
  std::printf("edge flips on a stretched icosphere: %d flips, triangles below 20 degrees %.1f%% -> %.1f%%, "
              "smallest angle %.1f -> %.1f degrees\n",
    flips, 100 * thinShare(mesh.triangles(), x), 100 * thinShare(flipped, x),
    smallestAngle(mesh, x).angle * 180 / M_PI, closed ? smallestAngle(after, x).angle * 180 / M_PI : 0.0);
  SW_CHECK(flips > 0 && closed, "flips leave a closed 2-manifold: " << error);
  // Each flip raises the smaller angle of its pair, so the smallest angle never drops; the vertices
  // stay, so triangles thin because of the vertex spacing itself stay thin.
  SW_CHECK(thinShare(flipped, x) < 0.75 * thinShare(mesh.triangles(), x) &&
      smallestAngle(after, x).angle >= smallestAngle(mesh, x).angle,
    "flips cut the thin triangles by a quarter or more and never lower the smallest angle");
  const double v0 = enclosedVolume(mesh, x), v1 = enclosedVolume(after, x);
  SW_CHECK(std::abs(v1 - v0) < 0.02 * v0, "the shape is kept: volume within 2% (" << v0 << " -> " << v1 << ")");

  // No pair of triangles on a curved surface is exactly coplanar: a zero dihedral limit flips nothing.
  settings.maxDihedral = 0;
  SW_CHECK(flipEdges(mesh, x, settings, flipped) == 0, "the dihedral limit keeps ridges");

  // In the evolver: flips after each step, and the evolver carries on with the new triangles.
  EvolverSettings evolve;
  evolve.C2 = 0;
  evolve.C = 0;
  evolve.timeStep = 1e-3;
  evolve.edgeFlips = true;
  Evolver evolver(mesh, evolve);
  int total = 0;
  for (int k = 0; k < 5; ++k)
  {
    const StepReport r = evolver.step();
    SW_CHECK(r.ok(), "flow with flips, step " << k + 1 << ": " << r.message);
    total += r.flips;
  }
  SW_CHECK(total > 0 && evolver.mesh().triangles() != mesh.triangles() &&
      thinShare(evolver.mesh().triangles(), evolver.positions()) < thinShare(mesh.triangles(), x),
    "the evolver flips as it goes (" << total << " flips)");
}
// Euler characteristic V - E + F of a closed triangle surface: V - F / 2.
int eulerCharacteristic(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
{
  return static_cast<int>(points.size()) - static_cast<int>(triangles.size()) / 2;
}

void edgeCollapses()
{
  // A needle: one vertex of an icosphere moved to within 1% of a neighbour.
  TriangleSurface needle = icosphere(3);
  const SurfaceMesh mesh = meshOf(needle);
  const int a = 0, b = mesh.ring(mesh.ringBegin(0));
  needle.points[a] = needle.points[b] + 0.01 * (needle.points[a] - needle.points[b]);
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> kept;
  const int n = collapseEdges(mesh, needle.points, CollapseSettings(), points, triangles, kept);
  SurfaceMesh after;
  std::string error;
  const bool closed = SurfaceMesh::build(points, triangles, after, error);
  std::printf("edge collapses: a needle of %.2f degrees, %d collapse(s), smallest angle then %.1f degrees\n",
    smallestAngle(mesh, needle.points).angle * 180 / M_PI, n,
    closed ? smallestAngle(after, points).angle * 180 / M_PI : 0.0);
  SW_CHECK(n == 1 && closed, "one collapse, a closed 2-manifold: " << error);
  SW_CHECK(points.size() == needle.points.size() - 1 && kept.size() == points.size() &&
      eulerCharacteristic(points, triangles) == 2,
    "one vertex fewer, same genus");
  SW_CHECK(smallestAngle(after, points).angle > 20 * M_PI / 180, "no thin triangle left");

  // A cap: a vertex of valence 3 put into a face, almost on one of its edges. The flat triangle goes
  // with it.
  TriangleSurface cap = icosphere(2);
  const std::array<int, 3> face = cap.triangles[7];
  const Vec3 centre = (cap.points[face[0]] + cap.points[face[1]] + cap.points[face[2]]) / 3;
  const Vec3 middle = 0.5 * (cap.points[face[0]] + cap.points[face[1]]);
  const int v = static_cast<int>(cap.points.size());
  cap.points.push_back(middle + 0.01 * (centre - middle));
  cap.triangles[7] = { face[0], face[1], v };
  cap.triangles.push_back({ face[1], face[2], v });
  cap.triangles.push_back({ face[2], face[0], v });
  const SurfaceMesh capped = meshOf(cap);
  SW_CHECK(collapseEdges(capped, cap.points, CollapseSettings(), points, triangles, kept) == 1 &&
      points.size() == 162 && triangles.size() == 320 && SurfaceMesh::build(points, triangles, after, error),
    "the cap's vertex is merged away: the icosphere's counts again, closed");

  // Where the two ends of an edge share a third neighbour, merging them would pinch the surface:
  // the two-vertex-wide waist of a tetrahedron-like cap is left alone (link condition).
  TriangleSurface tetra;
  tetra.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.001, 0.001, 1) };
  tetra.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } };
  SW_CHECK(collapseEdges(meshOf(tetra), tetra.points, CollapseSettings(), points, triangles, kept) == 0,
    "no collapse leaves fewer than four vertices or breaks the link condition");
}

} // namespace

int TestEvolver(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    icospheres();
    distanceSampling();
    stabilityScaling();
    redistributionDoesItsJob();
    advection();
    failureIsReported();
    scaledEvolution();
    leavingTheDomain();
    edgeFlips();
    edgeCollapses();
    badInput();
  });
  return testing::finish("TestEvolver");
}
