// The distances a wrap moves on, made from its target and plan: the target's field (given, or
// computed on the plan's lattice with Mesh Signed Distance's algorithm), closed over the gaps
// narrower than the Gap Size, and exact near the target.
#ifndef ShrinkWrap_WrapFields_h
#define ShrinkWrap_WrapFields_h

#include "Common/Notes.h"
#include "Common/Progress.h"
#include "Common/Status.h"
#include "Distance/TargetDistance.h"
#include "Wrap/WrapPlan.h"

namespace shrinkwrap
{

struct WrapFields
{
  TargetDistance driving; // to the target closed over gaps narrower than the Gap Size
  TargetDistance target;  // to the target itself: what the output's closeness measures
};

// The fields of the plan's target. Notes say when the field is unsigned or signed by winding
// number; a Status says why there are none (or that progress asked to stop).
Status makeWrapFields(const WrapTarget& target, const WrapPlan& plan, const Progress& progress,
  Notes& notes, WrapFields& fields);

// The fields from the target's grid (signed or not) and, when `exact` is given, the target itself
// for the near field; "aborted" when `progress` asks to stop.
Status wrapFields(DistanceGrid grid, bool isSigned, std::shared_ptr<const DistanceSource> exact,
  const WrapPlan& plan, WrapFields& fields, const Progress& progress = Progress());

// The fields of a wrap onto points from their unsigned grid: driven by the distance to the points
// closed by a ball of half the Gap Size (a surface through the outer points that spans the gaps
// between them), measured to the points themselves. With `polygons` (Polygons and Points), `grid`
// is the distance to both, and near them the wrap lands on the nearer of the polygons and the
// points' fitted surface. "aborted" when `progress` asks to stop.
Status pointWrapFields(DistanceGrid grid, const PointCloud& cloud, const WrapPlan& plan,
  WrapFields& fields, std::shared_ptr<const DistanceSource> polygons = nullptr,
  const Progress& progress = Progress());

} // namespace shrinkwrap

#endif
