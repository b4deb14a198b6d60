#include "Wrap/Closeness.h"

#include "Common/Parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace shrinkwrap
{

std::vector<Vec3> samplePoints(const TriangleSoup& soup, int count, unsigned seed)
{
  std::vector<double> areas;
  areas.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles)
  {
    areas.push_back(0.5 *
      (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]).norm());
  }
  std::vector<Vec3> samples(soup.points);
  if (areas.empty() || std::all_of(areas.begin(), areas.end(), [](double a) { return !(a > 0); }))
  {
    return samples;
  }
  std::mt19937_64 random(seed);
  std::discrete_distribution<int> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0, 1);
  samples.reserve(samples.size() + std::max(count, 0));
  for (int k = 0; k < count; ++k)
  {
    const auto& t = soup.triangles[pick(random)];
    double u = unit(random), v = unit(random);
    if (u + v > 1)
    {
      u = 1 - u;
      v = 1 - v;
    }
    samples.push_back(soup.points[t[0]] + u * (soup.points[t[1]] - soup.points[t[0]]) +
      v * (soup.points[t[2]] - soup.points[t[0]]));
  }
  return samples;
}

namespace
{
template <typename Points, typename SquaredDistance>
OneSided distancesFrom(const Points& from, SquaredDistance&& squared)
{
  std::vector<double> d(from.size());
  parallelFor(0, static_cast<Index>(from.size()), kQueryGrain, [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      d[i] = std::sqrt(squared(from[i]));
    }
  });
  OneSided sided;
  for (double v : d)
  {
    sided.mean += v;
    sided.largest = std::max(sided.largest, v);
  }
  sided.mean /= std::max<std::size_t>(d.size(), 1);
  return sided;
}
} // namespace

OneSided oneSided(const std::vector<Vec3>& from, const AABBTree& to)
{
  return distancesFrom(from, [&](const Vec3& p) { return to.closestPoint(p).squaredDistance; });
}

Closeness measureCloseness(const TriangleSoup& wrap, const DistanceSource& wrapSource,
  const SquaredDistance& toTarget, const TriangleSoup* targetTriangles,
  const PointSource* targetPoints, int samples)
{
  Closeness c;
  c.wrapToTarget = distancesFrom(samplePoints(wrap, samples, 1), toTarget);
  auto toWrap = [&](const Vec3& p) {
    return wrapSource.closestPoint(p, std::numeric_limits<double>::infinity()).squaredDistance;
  };
  if (targetTriangles)
  {
    c.targetToWrap = distancesFrom(samplePoints(*targetTriangles, samples, 2), toWrap);
  }
  else if (targetPoints)
  {
    c.targetToWrap = distancesFrom(targetPoints->points(), toWrap);
  }
  return c;
}

} // namespace shrinkwrap
