// Gap Size: the wrap bridges gaps and holes narrower than the gap size and enters wider ones. The
// field that drives it is the distance to the target's morphological closing by a ball of radius
// gap / 2: the target dilated by the radius, D = {d < radius}, then eroded by it. Where no gap is
// bridged the closing is the target itself; across a narrower gap it is a membrane, and the wrap
// stops on it instead of pushing into the gap from both sides (a D > 0 front would, and meet
// itself).
//
// Closing then dilating equals dilating, so outside D the distance to the closing is d itself, and
// inside D it is radius - e, e the distance to D's boundary. e comes from sites on that boundary,
// one per node near it (radius beyond the target's closest point, on the line through the node;
// where another part of the target is nearer, moved onto the crease where the two fronts meet),
// spread over the grid by the closest-point passes; a node whose own boundary point is clear has e
// = radius - d exactly. No contour, no second distance field (which would cost several times more).
#ifndef ShrinkWrap_GapClosing_h
#define ShrinkWrap_GapClosing_h

#include "Common/Progress.h"
#include "Common/Status.h"
#include "Distance/DistanceGrid.h"

namespace shrinkwrap
{

class DistanceSource;

// The distance to the closing of the target of `field` by a ball of `radius` (in the field's
// units), on the same lattice. `target`, if given, is the target itself (its closest points place
// the sites; without it the grid's gradient does). `fillCavities`: pockets of the complement of D
// that the grid's border does not reach join D (a point set's union of balls is a shell: eroded
// from its cavities too, it would open every gap between the points again). A radius below a
// quarter of a cell closes nothing: `closed` is `field`. Fails "aborted" when `progress` asks to
// stop.
Status closingField(const DistanceGrid& field, double radius, const DistanceSource* target,
  bool fillCavities, DistanceGrid& closed, const Progress& progress = Progress());

} // namespace shrinkwrap

#endif
