// How close two surfaces lie, as a user judges a wrap: points sampled uniformly by area on each
// surface (its vertices, then random points), and from each the distance to the other surface;
// the mean and the largest of one side's distances. The run summary and the benchmark measure
// alike.
#ifndef ShrinkWrap_Closeness_h
#define ShrinkWrap_Closeness_h

#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Distance/PointSource.h"

#include <functional>
#include <vector>

namespace shrinkwrap
{

// The soup's points, then `count` points uniformly by area on its triangles (drawn from `seed`:
// the same soup and seed give the same points).
std::vector<Vec3> samplePoints(const TriangleSoup& soup, int count, unsigned seed = 1);

struct OneSided
{
  double mean = 0;    // in the surfaces' units
  double largest = 0; // in the surfaces' units
};
// Distances from `from` to the nearest point of `to` (on all cores).
OneSided oneSided(const std::vector<Vec3>& from, const AABBTree& to);

// Both ways between a wrap and its target (triangles, or points where it has none).
struct Closeness
{
  OneSided wrapToTarget;
  OneSided targetToWrap;
};
// The squared distance from a point to a surface.
using SquaredDistance = std::function<double(const Vec3&)>;
// `samples` random points on each surface beside their vertices: the wrap's measured by `toTarget`,
// the target's (its triangles, or a cloud's own points) by `wrapSource`, the wrap's own triangles
// as a distance source.
Closeness measureCloseness(const TriangleSoup& wrap, const DistanceSource& wrapSource,
  const SquaredDistance& toTarget, const TriangleSoup* targetTriangles,
  const PointSource* targetPoints, int samples);

} // namespace shrinkwrap

#endif
