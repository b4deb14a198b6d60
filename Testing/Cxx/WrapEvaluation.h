// How a wrap is judged (issue #10), for the tests and the benchmark alike: points sampled uniformly
// by area on both surfaces (plus their vertices), one-sided distances to the other surface through
// an AABB tree (mean and largest, in percent of the target's bounding-box diagonal; Closeness.h,
// as the run summary measures them), self-intersections, closed and manifold, genus, the share of
// triangles with a minimum angle below 20 degrees.
#ifndef ShrinkWrap_WrapEvaluation_h
#define ShrinkWrap_WrapEvaluation_h

#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Surface/MeshQuality.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"
#include "Wrap/Closeness.h"

#include <functional>
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

// The soup's vertices, then `count` points uniformly by area on it (as the run summary samples).
using shrinkwrap::samplePoints;

// From each point to the nearest point of `to`, in percent of `diagonal`.
inline OneSided oneSided(
  const std::vector<shrinkwrap::Vec3>& from, const shrinkwrap::TriangleSoup& to, double diagonal)
{
  const shrinkwrap::OneSided d = shrinkwrap::oneSided(from, shrinkwrap::AABBTree(to));
  return { 100 * d.mean / diagonal, 100 * d.largest / diagonal };
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
