// Rim coverage (issue #10, RimCoverage.h): rim samples along every edge at most the spacing apart, each
// rim vertex once; a sample outside the surface moves the nearest triangle's corners so that its
// nearest point reaches the sample; samples inside, within the tolerance or beyond the reach move
// nothing. Whole wraps of an open CAD shell: Cxx.TestShrinkWrapCGALMeshes.
#include "Icosphere.h"
#include "RimCoverage.h"
#include "TestUtilities.h"
#include "TriangleDistance.h"

#include <vtkSMPTools.h>

#include <limits>

namespace
{
using namespace shrinkwrap;

// The nearest point of the surface to p.
Vec3 nearestOn(const std::vector<Vec3>& y, const std::vector<std::array<int, 3>>& triangles, const Vec3& p)
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
  SW_CHECK(s.size() == 16 && gap <= 0.3, "rim samples: every vertex once, at most the spacing apart (" << s.size()
    << " samples, largest gap " << gap << ")");
  SW_CHECK(rimSamples({ { a, b } }, 0).empty(), "no spacing, no samples");
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
    "a sample outside: the nearest triangle's corners carry its nearest point onto it (" << moving(m)
      << " vertices, " << reached << " left)");
  SW_CHECK(moving(rimMoves(sphere, { out * (0.8 / 1.1) }, 0.01, 0.5)) == 0, "a sample inside moves nothing");
  SW_CHECK(moving(rimMoves(sphere, { out * (1.005 / 1.1) }, 0.01, 0.5)) == 0, "a sample within the tolerance moves nothing");
  SW_CHECK(moving(rimMoves(sphere, { out * 2.0 }, 0.01, 0.5)) == 0, "a sample beyond the reach moves nothing");
  // Two samples pulling at the same vertex: the larger move wins.
  const Vec3 far = y[0] * 1.3, near = y[0] * 1.1;
  const std::vector<Vec3> both = rimMoves(sphere, { near, far }, 0.01, 0.5);
  SW_CHECK((both[0] - (far - y[0])).norm() < 1e-12, "the larger of two moves at a vertex wins");
}
} // namespace

int TestRimCoverage(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    samples();
    moves();
  });
  return testing::finish("TestRimCoverage");
}
