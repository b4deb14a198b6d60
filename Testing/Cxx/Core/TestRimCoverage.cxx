// Rim coverage (issue #10, RimCoverage.h): a mesh's rims are its edges of one triangle and, below a
// crease angle, its sharp creases; rim samples along every edge at most the spacing apart, each rim
// vertex once; a sample outside the surface moves the nearest triangle's corners so that its
// nearest point reaches the sample; samples inside, within the tolerance or beyond the reach move
// nothing; the vertices of a sample's nearest point hold it by their weights there. Whole wraps of
// an open CAD shell: Cxx.TestShrinkWrapCGALMeshes.
#include "Distance/DistanceSource.h"
#include "Distance/TriangleDistance.h"
#include "Evolution/RimCoverage.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <limits>

namespace
{
using namespace shrinkwrap;

// The nearest point of the surface to p.
Vec3 nearestOn(
  const std::vector<Vec3>& y, const std::vector<std::array<int, 3>>& triangles, const Vec3& p)
{
  Vec3 best = Vec3::Zero();
  double d2 = std::numeric_limits<double>::infinity();
  for (const auto& t : triangles)
  {
    const Vec3 q = closestPointOnTriangle(p, y[t[0]], y[t[1]], y[t[2]]).point;
    if ((q - p).squaredNorm() < d2)
    {
      d2 = (q - p).squaredNorm();
      best = q;
    }
  }
  return best;
}

int moving(const std::vector<Vec3>& moves)
{
  int n = 0;
  for (const Vec3& m : moves)
  {
    n += m != Vec3::Zero();
  }
  return n;
}

void samples()
{
  // A closed square rim of four edges of length 1, sampled every 0.3: 4 pieces an edge, 16 points.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  const auto s = rimSamples({ { a, b }, { b, c }, { c, d }, { d, a } }, 0.3);
  double gap = 0;
  for (const Vec3& p : s)
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& q : s)
    {
      nearest = p == q ? nearest : std::min(nearest, (p - q).norm());
    }
    gap = std::max(gap, nearest);
  }
  SW_CHECK(s.size() == 16 && gap <= 0.3,
    "rim samples: every vertex once, at most the spacing apart ("
      << s.size() << " samples, largest gap " << gap << ")");
  SW_CHECK(rimSamples({ { a, b } }, 0).empty(), "no spacing, no samples");
}

// A unit cube of 12 triangles (each face split along a diagonal), outward; without its top (z = 1)
// when open.
TriangleSoup cube(bool open)
{
  TriangleSoup soup;
  for (int k = 0; k < 8; ++k)
  {
    soup.points.push_back(Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  }
  soup.triangles = { { 0, 2, 1 }, { 1, 2, 3 }, { 0, 1, 5 }, { 0, 5, 4 }, { 1, 3, 7 }, { 1, 7, 5 },
    { 3, 2, 6 }, { 3, 6, 7 }, { 2, 0, 4 }, { 2, 4, 6 } };
  if (!open)
  {
    soup.triangles.push_back({ 4, 5, 7 });
    soup.triangles.push_back({ 4, 7, 6 });
  }
  return soup;
}

void rims()
{
  const TriangleSource closed(cube(false)), open(cube(true));
  SW_CHECK(closed.rims(180).empty(), "a closed cube has no rims");
  SW_CHECK(closed.rims(45).size() == 12 && closed.rims(91).empty(),
    "a cube's 12 edges are creases of 90 degrees, its faces' diagonals none ("
      << closed.rims(45).size() << ")");
  SW_CHECK(open.rims(180).size() == 4 && open.rims(45).size() == 12,
    "an open cube: 4 rims, and its 8 other edges creases (" << open.rims(180).size() << ", "
                                                            << open.rims(45).size() << ")");
  const TriangleSoup sphere = icosphere(3);
  SW_CHECK(TriangleSource(sphere).rims(45).empty(),
    "a sphere of 1280 triangles has no crease of 45 degrees");
}

void holds()
{
  SurfaceMesh sphere = testing::meshOf(icosphere(3));
  const auto& y = sphere.points();
  const std::vector<double> atVertex = rimHolds(sphere, { y[0] * 1.01 }, 0.1);
  int holding = 0;
  for (const double h : atVertex)
  {
    holding += h > 0;
  }
  SW_CHECK(
    holding == 1 && atVertex[0] == 1, "a sample over a vertex is held by that vertex alone, fully");
  const auto& t = sphere.triangles()[7];
  const Vec3 centre = (y[t[0]] + y[t[1]] + y[t[2]]) / 3.0;
  const std::vector<double> atFace = rimHolds(sphere, { centre }, 0.1);
  double sum = 0;
  holding = 0;
  for (const double h : atFace)
  {
    holding += h > 0;
    sum += h;
  }
  SW_CHECK(holding == 3 && std::abs(atFace[t[0]] - 1.0 / 3) < 1e-9 && std::abs(sum - 1) < 1e-9,
    "a sample at a triangle's centre is held by its corners, a third each");
  // Searched near the surface first, then over the whole reach: a sample farther out than the
  // first search is held the same way.
  const std::vector<double> fartherOut = rimHolds(sphere, { y[0] * 1.08 }, 0.1);
  SW_CHECK(
    fartherOut == atVertex, "a sample 0.08 out, within the reach 0.1, is held by that vertex");
  SW_CHECK(rimHolds(sphere, { y[0] * 1.5 }, 0.1) == std::vector<double>(y.size(), 0.0),
    "a sample beyond the reach is held by none");
}

void moves()
{
  SurfaceMesh sphere = testing::meshOf(icosphere(3)); // radius 1, edges about 0.15
  const auto& y = sphere.points();
  const Vec3 out = Vec3(0.3, 0.5, 0.8).normalized() * 1.1;
  std::vector<Vec3> m = rimMoves(sphere, { out }, 0.01, 0.5);
  std::vector<Vec3> moved = y;
  for (std::size_t v = 0; v < y.size(); ++v)
  {
    moved[v] += m[v];
  }
  const double reached = (nearestOn(moved, sphere.triangles(), out) - out).norm();
  SW_CHECK(moving(m) >= 1 && moving(m) <= 3 && reached < 1e-9,
    "a sample outside: the nearest triangle's corners carry its nearest point onto it ("
      << moving(m) << " vertices, " << reached << " left)");
  SW_CHECK(moving(rimMoves(sphere, { out * (0.8 / 1.1) }, 0.01, 0.5)) == 0,
    "a sample inside moves nothing");
  SW_CHECK(moving(rimMoves(sphere, { out * (1.005 / 1.1) }, 0.01, 0.5)) == 0,
    "a sample within the tolerance moves nothing");
  SW_CHECK(moving(rimMoves(sphere, { out * 2.0 }, 0.01, 0.5)) == 0,
    "a sample beyond the reach moves nothing");
  // Two samples pulling at the same vertex: the larger move wins.
  const Vec3 far = y[0] * 1.3, near = y[0] * 1.1;
  const std::vector<Vec3> both = rimMoves(sphere, { near, far }, 0.01, 0.5);
  SW_CHECK((both[0] - (far - y[0])).norm() < 1e-12, "the larger of two moves at a vertex wins");
}
} // namespace

int TestRimCoverage(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    rims();
    samples();
    moves();
    holds();
  });
  return testing::finish("TestRimCoverage");
}
