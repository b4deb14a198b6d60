// The target measured against its wrap (TargetMeasure.h) where the target's triangles are far
// larger than the wrap's: coarse icospheres inside a fine one, so that the distance is largest
// inside the coarse triangles (at their corners it is nearly 0), spikes into the sphere and
// slivers grazing it. The
// far shares are the same with the corners' distances (which settle parts without a search) as
// without; the largest distance is
// at least the largest at the points, about the largest a dense sample finds, and short of it by
// no more than the documented tolerance.
#include "Distance/DistanceSource.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"
#include "Wrap/Closeness.h"
#include "Wrap/TargetMeasure.h"

#include <algorithm>
#include <cmath>

namespace
{
using namespace shrinkwrap;

// The farthest a point of a triangle lies from its nearest corner, over the target's triangles, at
// the split's last depth: what largestDistance may leave short beside its relative tolerance.
double slackOf(const TriangleSoup& target)
{
  double longest = 0;
  for (const auto& t : target.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      longest = std::max(longest, (target.points[t[k]] - target.points[t[(k + 1) % 3]]).norm());
    }
  }
  // That farthest way is at most the longest edge (half of it, or the circumradius of an acute
  // triangle).
  return longest / (1 << kMaxSplitDepth);
}

// Parts settled by the corners' distances are judged as a search would: the same far shares at
// fractions of `largest`, some of them between 0 and 1.
void sharesAgree(
  const TriangleSoup& target, const DistanceSource& wrap, double largest, const std::string& name)
{
  const std::vector<double> atPoints =
    signedDistances(target.points.data(), target.points.size(), wrap);
  int partly = 0;
  for (double share : { 0.25, 0.5, 0.75, 0.9 })
  {
    const double distance = share * largest;
    const std::vector<double> searched = farShares(target, wrap, distance);
    const std::vector<double> settled = farShares(target, wrap, distance, &atPoints);
    for (double s : searched)
    {
      partly += s > 0 && s < 1;
    }
    SW_CHECK(settled == searched,
      name << ": the same far shares with and without the corners' distances at " << share);
  }
  SW_CHECK(partly > 0, name << ": some shares between 0 and 1");
}

void measured(int coarse, double radius, const std::string& name)
{
  const TriangleSoup target = icosphere(coarse, Vec3::Zero(), radius);
  const TriangleSource wrap(icosphere(6));
  const std::vector<double> atPoints =
    signedDistances(target.points.data(), target.points.size(), wrap);
  double largestAtPoints = 0;
  for (double d : atPoints)
  {
    largestAtPoints = std::max(largestAtPoints, std::abs(d));
  }
  double sampled = 0;
  for (const Vec3& x : samplePoints(target, 400000, 5))
  {
    sampled = std::max(sampled, std::sqrt(wrap.closestPoint(x, 1e30).squaredDistance));
  }
  const double tolerance = 0.02;
  const double largest = largestDistance(target, wrap, atPoints, tolerance);
  std::cout << name << ": largest at the points " << largestAtPoints << ", found " << largest
            << ", sampled densely " << sampled << std::endl;
  SW_CHECK(sampled > 3 * largestAtPoints, name << ": the case has its largest inside triangles");
  SW_CHECK(largest >= largestAtPoints, name << ": at least the largest at the points");
  SW_CHECK(largest <= sampled * (1 + tolerance), name << ": no more than a dense sample finds");
  SW_CHECK(largest >= sampled - std::max(tolerance * sampled, slackOf(target)),
    name << ": short of a dense sample's by no more than the tolerance or the split's depth");
  // Here the split reaches the tolerance: pieces over one wrap triangle settle by its distance.
  SW_CHECK(largest >= (1 - tolerance) * sampled, name << ": found to the tolerance");

  sharesAgree(target, wrap, sampled, name);
}

// Spikes from the wrap's surface towards its centre: the distance grows along them as fast as
// the way (the far shares' settling is exact only if its bound is).
TriangleSoup spikes()
{
  TriangleSoup soup;
  const TriangleSoup directions = icosphere(0);
  for (const Vec3& d : directions.points)
  {
    const Vec3 side = d.unitOrthogonal();
    const int base = static_cast<int>(soup.points.size());
    soup.points.push_back(d);
    soup.points.push_back(0.2 * d + 0.1 * side);
    soup.points.push_back(0.2 * d - 0.1 * side);
    soup.triangles.push_back({ base, base + 1, base + 2 });
  }
  return soup;
}

// Slivers that graze the sphere: their long edge passes 0.05 over it between ends 0.83 from it,
// so that near their middle the distance is far below what any corner's bound allows.
TriangleSoup grazing()
{
  TriangleSoup soup;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (double side : { -1.0, 1.0 })
    {
      const int base = static_cast<int>(soup.points.size());
      for (const Vec3& q : { Vec3(-1.5, 0, 1.05), Vec3(1.5, 0, 1.05), Vec3(0, 0.3, 1.05) })
      {
        Vec3 p(q[0], q[1], side * q[2]);
        std::swap(p[2], p[axis]);
        soup.points.push_back(p);
      }
      soup.triangles.push_back({ base, base + 1, base + 2 });
    }
  }
  return soup;
}
} // namespace

int TestTargetMeasure(int, char*[])
{
  measured(1, 1.0, "80 triangles in a sphere of 40,962 vertices");
  measured(3, 0.999, "1,280 triangles just inside it");
  sharesAgree(spikes(), TriangleSource(icosphere(6)), 0.8, "spikes into the sphere");
  sharesAgree(grazing(), TriangleSource(icosphere(6)), 0.83, "slivers grazing the sphere");
  return testing::finish("TestTargetMeasure");
}
