// Gap Size: the wrap bridges gaps and holes narrower than the gap size and enters wider ones. The
// field that drives it is the distance to the target's morphological closing by a ball of radius
// gap / 2: the target dilated by the radius (a contour of its field), then eroded by it. Where no gap
// is bridged the closing is the target itself; across a narrower gap it is a membrane, and the wrap
// stops on it instead of pushing into the gap from both sides (a D > 0 front would, and meet itself).
// (Closing then dilating equals dilating, so the distance to the closing is the distance to the
// dilated contour plus the radius, exactly outside the contour.)
#ifndef ShrinkWrap_GapClosing_h
#define ShrinkWrap_GapClosing_h

#include "DistanceGrid.h"
#include "Status.h"
#include "TriangleSurface.h"

#include <functional>

namespace shrinkwrap
{

// Marching cubes of a distance field at one value (the filters give VTK's Flying Edges).
using Contour = std::function<TriangleSurface(const DistanceGrid& field, double value)>;

// The distance to the closing of the target of `field` by a ball of `radius` (in the field's units),
// on the same lattice. A radius below a quarter of a cell closes nothing: `closed` is `field`.
Status closingField(const DistanceGrid& field, double radius, const Contour& contour, DistanceGrid& closed);

} // namespace shrinkwrap

#endif
