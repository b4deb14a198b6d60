// Where each vertex of a wrap stands on its target, so that values given on the target can be read
// on the wrap: on triangles, the triangle its closest point lies on and that point's barycentric
// weights on the triangle's corners; on points, the points of the fit under it with the fit's
// weights (PointSurface::fitWeights). Each vertex's weights sum to 1.
#ifndef ShrinkWrap_TargetFeet_h
#define ShrinkWrap_TargetFeet_h

#include "Common/TriangleSoup.h"
#include "Distance/PointSurface.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace shrinkwrap
{

struct TargetFeet
{
  std::vector<int> element;        // per vertex: the soup's triangle, or the nearest input point
  std::vector<std::int64_t> begin; // per vertex and one more: where its weights start below
  std::vector<int> points;         // the soup's (or the cloud's) point ids, by vertex
  std::vector<double> weights;     // the weight of each of those points
  std::size_t size() const { return this->element.size(); }
};

// The nearest point of a soup to a point: the triangle it lies on (its index in the soup; -1 for
// none) and the point.
using NearestOnSoup = std::function<std::pair<int, Vec3>(const Vec3&)>;
// The feet of points `x` on a triangle soup, found by `nearest` (on all cores).
TargetFeet feetOnTriangles(
  const std::vector<Vec3>& x, const TriangleSoup& soup, const NearestOnSoup& nearest);
// The feet of points `x` on a point cloud's fitted surface (on all cores).
TargetFeet feetOnPoints(const std::vector<Vec3>& x, const PointSurface& surface);

// The barycentric weights of p (a point on or near triangle a, b, c) on its corners, each in [0,
// 1]; the nearest corner alone for a degenerate triangle.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace shrinkwrap

#endif
