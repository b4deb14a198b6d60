// The AABB tree (Algorithm 1, line 1): its closest point equals the brute-force closest point over
// every triangle, for points near and far, on a soup with noise, duplicates and a degenerate
// triangle, and within a search radius it finds nothing beyond it.
#include "Distance/AABBTree.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <random>

namespace
{
using namespace shrinkwrap;

TriangleSoup noisySoup()
{
  TriangleSoup soup = icosphere(4, Vec3(0.2, -0.1, 0.3), 1.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  for (Vec3& p : soup.points)
  {
    p += Vec3(u(random), u(random), u(random));
  }
  soup.triangles.push_back(soup.triangles.front()); // a duplicate
  soup.triangles.push_back({ 0, 1, 1 });            // a segment
  soup.points.push_back(Vec3(3, 0, 0));             // a lone triangle far off
  soup.points.push_back(Vec3(3, 0.5, 0));
  soup.points.push_back(Vec3(3, 0, 0.5));
  const int n = static_cast<int>(soup.points.size());
  soup.triangles.push_back({ n - 3, n - 2, n - 1 });
  return soup;
}

void closestPoints()
{
  const TriangleSoup soup = noisySoup();
  const AABBTree tree(soup);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-2.5, 4);
  double worst = 0;
  int wrongFeature = 0;
  for (int k = 0; k < 2000; ++k)
  {
    const Vec3 p(u(random), 0.5 * u(random), 0.5 * u(random));
    const ClosestHit hit = tree.closestPoint(p);
    const double exact = testing::bruteForceDistance(soup, p);
    worst = std::max(worst, std::abs(std::sqrt(hit.squaredDistance) - exact));
    const auto& t = soup.triangles[hit.triangle];
    const TrianglePoint again =
      closestPointOnTriangle(p, soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
    wrongFeature += (again.point - hit.point).norm() > 1e-12;
  }
  std::printf("AABB tree: 2000 queries, largest difference from brute force %.3g\n", worst);
  SW_CHECK(worst < 1e-12, "the tree's closest point is the brute-force one");
  SW_CHECK(wrongFeature == 0, "the hit's point lies on its triangle");
  SW_CHECK(tree.bounds().max.x() >= 3 && tree.bounds().min.x() < -0.7,
    "the root box holds every triangle");
}

void searchRadius()
{
  const TriangleSoup soup = icosphere(3);
  const AABBTree tree(soup);
  const ClosestHit outside = tree.closestPoint(Vec3(3, 0, 0), 1.0); // 2 away, radius 1
  SW_CHECK(outside.triangle < 0, "nothing within the radius: no hit");
  const ClosestHit within = tree.closestPoint(Vec3(3, 0, 0), 4.1);
  SW_CHECK(within.triangle >= 0 && std::abs(std::sqrt(within.squaredDistance) - 2) < 0.01,
    "a hit within it");
}
} // namespace

int TestAABBTree(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    closestPoints();
    searchRadius();
  });
  return testing::finish("TestAABBTree");
}
