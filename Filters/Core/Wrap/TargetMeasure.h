// The target measured against its wrap, for the user to see where the wrap leaves it: the signed
// distance from points of the target to the closed wrap (> 0 outside the wrap, < 0 inside), and per
// triangle of the target the share of its area that lies farther than a given distance from the
// wrap (a slot the wrap bridged, a fin it cut off).
#ifndef ShrinkWrap_TargetMeasure_h
#define ShrinkWrap_TargetMeasure_h

#include "Common/TriangleSoup.h"
#include "Distance/DistanceSource.h"

#include <vector>

namespace shrinkwrap
{

// Signed distances from `count` points to the wrap (a TriangleSource of a closed surface: its
// pseudonormals give the side), in the target's units (on all cores).
std::vector<double> signedDistances(
  const Vec3* points, std::size_t count, const DistanceSource& wrap);

// Per triangle of `target`, the share (0 to 1) of its area farther than `distance` from the wrap:
// the triangle cut into n^2 equal parts (n from 1 to kMaxFarSplits, parts no longer than half
// `distance`), each judged at its centroid (on all cores). `atPoints`, the distances at the
// target's points (signedDistances), if given, settle the triangles whose corners all lie nearer
// (or all farther) than `distance` by more than their longest edge, and the parts whose centroid
// does so by more than its way from a corner: the distance changes by no more than the way.
constexpr int kMaxFarSplits = 8;
std::vector<double> farShares(const TriangleSoup& target, const DistanceSource& wrap,
  double distance, const std::vector<double>* atPoints = nullptr);

// The largest distance from the target's triangles to the wrap, found to `tolerance` (relative):
// from `atPoints` (the distances at the target's points), each triangle split in four where the
// distance over it could exceed the largest found by more than the tolerance and by more than
// the way across a piece of the last depth, down to kMaxSplitDepth levels (on all cores). Over a
// piece the distance is at most its corners' plus the way to the nearest corner, and at most the
// distance from its farthest corner to the wrap triangle nearest to one of its corners (`wrap`'s
// triangles, where it has them). At least the largest at the points; short of the largest by at
// most `tolerance` of it, or by the farthest a point of a 32nd-size piece of a triangle lies from
// the piece's nearest corner; in the target's units.
constexpr int kMaxSplitDepth = 5;
double largestDistance(const TriangleSoup& target, const DistanceSource& wrap,
  const std::vector<double>& atPoints, double tolerance = 0.02);

} // namespace shrinkwrap

#endif
