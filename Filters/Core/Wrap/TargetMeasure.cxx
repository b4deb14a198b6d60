#include "Wrap/TargetMeasure.h"

#include "Common/Parallel.h"
#include "Distance/TriangleDistance.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

namespace shrinkwrap
{

namespace
{
constexpr double kEverywhere = std::numeric_limits<double>::infinity();
// A bound within this factor of the distance it is compared with is not trusted over rounding.
constexpr double kSure = 1 - 1e-9;

// The farthest a point of the triangle lies from its nearest corner: the circumradius of an acute
// triangle, half the longest edge of another.
double reach(const std::array<Vec3, 3>& p)
{
  const double a = (p[1] - p[2]).norm(), b = (p[2] - p[0]).norm(), c = (p[0] - p[1]).norm();
  const double longest = std::max({ a, b, c });
  const double squares = a * a + b * b + c * c;
  if (2 * longest * longest >= squares) // right or obtuse
  {
    return 0.5 * longest;
  }
  const double twiceArea = (p[1] - p[0]).cross(p[2] - p[0]).norm();
  return twiceArea > 0 ? a * b * c / (2 * twiceArea) : 0.5 * longest;
}

// A bound on the distance over the triangle p from the wrap's triangles w (-1: none): no point of
// it lies farther from the wrap than from w[k], and no farther from w[k] than its farthest corner
// (the distance to a triangle is convex). Infinite without a triangle.
double boundByNearestTriangles(
  const std::array<Vec3, 3>& p, const std::array<int, 3>& w, const TriangleSoup* soup)
{
  double bound = kEverywhere;
  for (int k = 0; k < 3 && soup; ++k)
  {
    if (w[k] < 0 || (k > 0 && w[k] == w[k - 1]) || (k == 2 && w[2] == w[0]))
    {
      continue;
    }
    const auto& t = soup->triangles[w[k]];
    const Vec3 &a = soup->points[t[0]], &b = soup->points[t[1]], &c = soup->points[t[2]];
    double farthest = 0;
    for (const Vec3& x : p)
    {
      farthest = std::max(farthest, (closestPointOnTriangle(x, a, b, c).point - x).squaredNorm());
    }
    bound = std::min(bound, std::sqrt(farthest));
  }
  return bound;
}
} // namespace

std::vector<double> signedDistances(
  const Vec3* points, std::size_t count, const DistanceSource& wrap)
{
  std::vector<double> d(count);
  parallelFor(0, static_cast<Index>(count), kQueryGrain, [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      const SourcePoint p = wrap.closestPoint(points[i], kEverywhere);
      const double distance = p.found ? std::sqrt(p.squaredDistance) : kEverywhere;
      d[i] = p.side < 0 ? -distance : distance;
    }
  });
  return d;
}

std::vector<double> farShares(const TriangleSoup& target, const DistanceSource& wrap,
  double distance, const std::vector<double>* atPoints)
{
  std::vector<double> share(target.triangles.size(), 0.0);
  const double squared = distance * distance;
  parallelFor(0, static_cast<Index>(share.size()), kQueryGrain, [&](Index b, Index e) {
    for (Index t = b; t < e; ++t)
    {
      const auto& c = target.triangles[t];
      const Vec3& a = target.points[c[0]];
      const Vec3& u = target.points[c[1]] - a;
      const Vec3& v = target.points[c[2]] - a;
      const double longest = std::max({ u.norm(), v.norm(), (u - v).norm() });
      std::array<double, 3> d{};
      if (atPoints)
      {
        d = { std::abs((*atPoints)[c[0]]), std::abs((*atPoints)[c[1]]),
          std::abs((*atPoints)[c[2]]) };
        if (std::max({ d[0], d[1], d[2] }) + longest <= distance)
        {
          continue; // near everywhere: share 0
        }
        if (std::min({ d[0], d[1], d[2] }) - longest > distance)
        {
          share[t] = 1; // far everywhere
          continue;
        }
      }
      const int n = std::clamp(static_cast<int>(std::ceil(longest / (0.5 * distance))), 1,
        distance > 0 ? kMaxFarSplits : 1);
      int far = 0;
      const std::array<Vec3, 3> corner = { a, target.points[c[1]], target.points[c[2]] };
      auto judge = [&](double s, double r) { // the part's centroid at a + s u + r v
        const Vec3 x = a + s * u + r * v;
        // The distance changes by no more than the way from a corner: a part that near (or that
        // far) from a corner is settled without a search (kSure keeps the rounding on its side).
        if (atPoints)
        {
          double nearest = kEverywhere, farthest = 0;
          for (int k = 0; k < 3; ++k)
          {
            const double way = (x - corner[k]).norm();
            nearest = std::min(nearest, d[k] + way);
            farthest = std::max(farthest, d[k] - way);
          }
          if (nearest <= kSure * distance)
          {
            return;
          }
          if (farthest > distance / kSure && std::isfinite(farthest))
          {
            ++far;
            return;
          }
        }
        const SourcePoint p = wrap.closestPoint(x, kEverywhere);
        far += !p.found || p.squaredDistance > squared;
      };
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; i + j < n; ++j)
        {
          judge((i + 1.0 / 3) / n, (j + 1.0 / 3) / n); // the parts pointing as the triangle
          if (i + j + 1 < n)
          {
            judge((i + 2.0 / 3) / n, (j + 2.0 / 3) / n); // the ones pointing against it
          }
        }
      }
      share[t] = static_cast<double>(far) / (n * n);
    }
  });
  return share;
}

double largestDistance(const TriangleSoup& target, const DistanceSource& wrap,
  const std::vector<double>& atPoints, double tolerance)
{
  const TriangleSoup* wrapTriangles = wrap.triangles();
  double start = 0;
  for (const auto& t : target.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      start = std::max(start, std::abs(atPoints[t[k]]));
    }
  }
  std::atomic<double> best(start);
  auto raise = [&](double d) {
    double seen = best.load();
    while (d > seen && !best.compare_exchange_weak(seen, d))
    {
    }
  };
  struct Piece
  {
    std::array<Vec3, 3> corner;
    std::array<double, 3> d; // unsigned distances at the corners
    std::array<int, 3> foot; // the wrap's triangles nearest to the corners (-1: not known)
    int depth;
  };
  auto nearestAt = [&](const Vec3& x, double& distance, int& foot) {
    const SourcePoint p = wrap.closestPoint(x, kEverywhere);
    distance = p.found ? std::sqrt(p.squaredDistance) : 0.0;
    foot = p.found ? p.element : -1;
  };
  parallelFor(0, static_cast<Index>(target.triangles.size()), kQueryGrain, [&](Index b, Index e) {
    std::vector<Piece> stack;
    for (Index t = b; t < e; ++t)
    {
      const auto& c = target.triangles[t];
      // What the split's depth may leave short anyway (the reach of a piece at the last depth): no
      // piece need come nearer.
      const double slack =
        reach({ target.points[c[0]], target.points[c[1]], target.points[c[2]] }) /
        (1 << kMaxSplitDepth);
      stack.push_back({ { target.points[c[0]], target.points[c[1]], target.points[c[2]] },
        { std::abs(atPoints[c[0]]), std::abs(atPoints[c[1]]), std::abs(atPoints[c[2]]) },
        { -1, -1, -1 }, 0 });
      while (!stack.empty())
      {
        const Piece piece = stack.back();
        stack.pop_back();
        const auto& [p, d, w, depth] = piece;
        const double enough = std::max((1 + tolerance) * best.load(), best.load() + slack);
        if (depth >= kMaxSplitDepth || std::max({ d[0], d[1], d[2] }) + reach(p) <= enough ||
          boundByNearestTriangles(p, w, wrapTriangles) <= enough)
        {
          continue;
        }
        const std::array<Vec3, 3> mid = { 0.5 * (p[0] + p[1]), 0.5 * (p[1] + p[2]),
          0.5 * (p[2] + p[0]) };
        std::array<double, 3> dm;
        std::array<int, 3> wm;
        for (int k = 0; k < 3; ++k)
        {
          nearestAt(mid[k], dm[k], wm[k]);
        }
        raise(std::max({ dm[0], dm[1], dm[2] }));
        stack.push_back(
          { { p[0], mid[0], mid[2] }, { d[0], dm[0], dm[2] }, { w[0], wm[0], wm[2] }, depth + 1 });
        stack.push_back(
          { { mid[0], p[1], mid[1] }, { dm[0], d[1], dm[1] }, { wm[0], w[1], wm[1] }, depth + 1 });
        stack.push_back(
          { { mid[2], mid[1], p[2] }, { dm[2], dm[1], d[2] }, { wm[2], wm[1], w[2] }, depth + 1 });
        stack.push_back({ mid, dm, wm, depth + 1 });
      }
    }
  });
  return best.load();
}

} // namespace shrinkwrap
