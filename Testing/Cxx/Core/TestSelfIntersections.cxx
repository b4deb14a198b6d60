// Self-intersections of a surface (issue #10): an icosphere has none; two icospheres that overlap
// cross along a circle, and exactly the triangles near it are flagged; one vertex pushed through the
// opposite side makes its fan cross; shared vertices and edges are never counted.
// And TargetDistance: near the target, d and grad d are the exact distance and direction to it.
#include "Icosphere.h"
#include "SelfIntersections.h"
#include "SignedDistance.h"
#include "TargetDistance.h"
#include "TestUtilities.h"

namespace
{
using namespace shrinkwrap;

void selfIntersections()
{
  const TriangleSurface sphere = icosphere(3, Vec3::Zero(), 1.0);
  SW_CHECK(findSelfIntersections(sphere.points, sphere.triangles).pairs == 0, "an icosphere does not cross itself");

  TriangleSurface two = sphere;
  const TriangleSurface other = icosphere(3, Vec3(1.0, 0.1, 0.05), 1.0);
  const int offset = static_cast<int>(two.points.size());
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  for (auto t : other.triangles)
  {
    two.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const SelfIntersections crossing = findSelfIntersections(two.points, two.triangles);
  int flagged = 0, far = 0;
  for (std::size_t t = 0; t < two.triangles.size(); ++t)
  {
    const Vec3 c = (two.points[two.triangles[t][0]] + two.points[two.triangles[t][1]] + two.points[two.triangles[t][2]]) / 3;
    const Vec3 other = t < sphere.triangles.size() ? Vec3(1.0, 0.1, 0.05) : Vec3::Zero();
    flagged += crossing.intersecting[t];
    // The circle where the spheres cross lies at distance 1 from both centres.
    far += crossing.intersecting[t] && std::abs((c - other).norm() - 1.0) > 0.15;
  }
  std::printf("two overlapping icospheres: %lld crossing pairs, %d triangles flagged\n", crossing.pairs, flagged);
  SW_CHECK(crossing.pairs > 20 && flagged > 20 && far == 0, "two overlapping spheres cross along their circle, and only there");

  TriangleSurface pushed = sphere;
  pushed.points[0] = -1.3 * pushed.points[0]; // through the other side
  SW_CHECK(findSelfIntersections(pushed.points, pushed.triangles).pairs > 0, "a vertex pushed through the sphere");
}

void exactNearTarget()
{
  const TriangleSurface sphere = icosphere(3, Vec3::Zero(), 1.0);
  const TriangleSoup soup{ sphere.points, sphere.triangles };
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.3, 32, 0 }, lattice);
  std::vector<float> values(lattice.nodeCount());
  computeSignedDistance(soup, lattice, {}, values.data());
  const auto source = std::make_shared<const TriangleSource>(soup);
  const TargetDistance grid(DistanceGrid(lattice, values)), exact(DistanceGrid(lattice, values), source, 2, true);
  const double h = lattice.spacing.maxCoeff();
  double gridError = 0, exactError = 0, gradientError = 0;
  for (int k = 0; k < 200; ++k)
  {
    // Points within a cell of the surface, outside and inside, off the vertices.
    const Vec3 direction = Vec3(std::sin(0.7 * k) * std::cos(1.3 * k), std::sin(0.7 * k) * std::sin(1.3 * k), std::cos(0.7 * k)).normalized();
    const Vec3 x = (1.0 + (k % 2 ? 0.5 : -0.5) * h) * direction;
    const double reference = testing::bruteForceDistance(soup, x) * (x.norm() > 1.0 ? 1 : -1);
    const SourcePoint p = source->closestPoint(x, 1e9);
    const Vec3 outward = (reference > 0 ? 1.0 : -1.0) * (x - p.point).normalized();
    gridError = std::max(gridError, std::abs(grid.sample(x).value - reference));
    const DistanceSample s = exact.sample(x);
    exactError = std::max(exactError, std::abs(s.value - reference));
    gradientError = std::max(gradientError, (s.gradient - outward).norm());
  }
  std::printf("within half a cell of a sphere: largest |d| error %.2g h from the grid, %.2g h exact; grad d off by %.2g\n",
    gridError / h, exactError / h, gradientError);
  SW_CHECK(exactError < 1e-9 * h && gradientError < 1e-9, "near the target d and grad d are exact");
  SW_CHECK(gridError > 0.01 * h, "where the grid alone is not");
}
} // namespace

int TestSelfIntersections(int, char*[])
{
  selfIntersections();
  exactNearTarget();
  return testing::finish("TestSelfIntersections");
}
