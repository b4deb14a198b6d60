// How a wrap is judged (issue #10), for the tests and the benchmark alike: points sampled uniformly
// by area on both surfaces (plus their vertices), one-sided distances to the other surface through
// an AABB tree (mean and largest, in percent of the target's bounding-box diagonal),
// self-intersections, closed and manifold, genus, the share of triangles with a minimum angle below
// 20 degrees.
#ifndef ShrinkWrap_WrapEvaluation_h
#define ShrinkWrap_WrapEvaluation_h

#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Surface/MeshQuality.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"

#include <functional>
#include <random>
#include <set>

namespace testing
{

struct OneSided
{
  double mean = 0, largest = 0; // percent of the diagonal
};

struct WrapFigures
{
  int vertices = 0;
  OneSided wrapToTarget, targetToWrap;
  long long selfIntersections = 0; // crossing triangle pairs (SelfIntersections.h)
  bool closedManifold = false;
  int components = 0;
  int genus = -1;         // summed over components; -1 when not closed and manifold
  double smallAngles = 0; // percent of triangles with a minimum angle below 20 degrees
};

// The soup's vertices, then `count` points uniformly by area on it.
inline std::vector<shrinkwrap::Vec3> samplePoints(
  const shrinkwrap::TriangleSoup& soup, int count, unsigned seed = 1)
{
  using shrinkwrap::Vec3;
  std::vector<double> areas;
  for (const auto& t : soup.triangles)
  {
    areas.push_back(0.5 *
      (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]).norm());
  }
  std::vector<Vec3> samples(soup.points);
  if (areas.empty())
  {
    return samples;
  }
  std::mt19937_64 random(seed);
  std::discrete_distribution<int> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0, 1);
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

inline OneSided oneSided(
  const std::vector<shrinkwrap::Vec3>& from, const shrinkwrap::TriangleSoup& to, double diagonal)
{
  const shrinkwrap::AABBTree tree(to);
  OneSided d;
  for (const auto& p : from)
  {
    const double distance = std::sqrt(tree.closestPoint(p).squaredDistance);
    d.mean += distance;
    d.largest = std::max(d.largest, distance);
  }
  d.mean = 100 * d.mean / std::max<std::size_t>(from.size(), 1) / diagonal;
  d.largest = 100 * d.largest / diagonal;
  return d;
}

inline WrapFigures evaluateWrap(const shrinkwrap::TriangleSoup& wrap,
  const shrinkwrap::TriangleSoup& target, int samples = 100000)
{
  WrapFigures f;
  f.vertices = static_cast<int>(wrap.points.size());
  if (wrap.triangles.empty())
  {
    return f;
  }
  const double diagonal = target.bounds().diagonal();
  f.wrapToTarget = oneSided(samplePoints(wrap, samples, 1), target, diagonal);
  f.targetToWrap = oneSided(samplePoints(target, samples, 2), wrap, diagonal);
  f.selfIntersections = shrinkwrap::findSelfIntersections(wrap.points, wrap.triangles).pairs;
  shrinkwrap::SurfaceMesh mesh;
  f.closedManifold = shrinkwrap::SurfaceMesh::build(wrap.points, wrap.triangles, mesh).ok();
  if (f.closedManifold)
  {
    // Components by a union-find over the triangles' vertices; genus from the Euler characteristic.
    std::vector<int> parent(wrap.points.size());
    for (std::size_t i = 0; i < parent.size(); ++i)
    {
      parent[i] = static_cast<int>(i);
    }
    std::function<int(int)> root = [&](int i) {
      return parent[i] == i ? i : parent[i] = root(parent[i]);
    };
    std::set<std::pair<int, int>> edges;
    for (const auto& t : wrap.triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        edges.insert({ std::min(a, b), std::max(a, b) });
        parent[root(a)] = root(b);
      }
    }
    std::set<int> roots;
    for (const auto& t : wrap.triangles)
    {
      roots.insert(root(t[0]));
    }
    f.components = static_cast<int>(roots.size());
    const long long chi = static_cast<long long>(wrap.points.size()) -
      static_cast<long long>(edges.size()) + static_cast<long long>(wrap.triangles.size());
    f.genus = static_cast<int>((2 * f.components - chi) / 2);
  }
  int small = 0;
  for (const auto& t : wrap.triangles)
  {
    small += shrinkwrap::triangleQuality(wrap.points[t[0]], wrap.points[t[1]], wrap.points[t[2]])
               .minAngle < 20;
  }
  f.smallAngles = 100.0 * small / wrap.triangles.size();
  return f;
}

} // namespace testing

#endif
