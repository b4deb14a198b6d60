// Connected components of a triangle surface, for the repairs a marching-cubes contour needs before
// it can start an evolution: specks (closed components around single grid nodes, which mean
// curvature shrinks to a point) and the walls of cavities.
#ifndef ShrinkWrap_Components_h
#define ShrinkWrap_Components_h

#include "Common/TriangleSoup.h"

namespace shrinkwrap
{

// Removes the connected components whose bounding box is smaller than `size` along every axis;
// returns how many were removed.
int removeSpecks(TriangleSoup& surface, double size);

// Removes the components that face the other way from the largest one: the walls of cavities, which
// a contour of an unsigned field has inside the target. Returns how many were removed.
int removeCavities(TriangleSoup& surface);

// The handles of a closed surface, summed over its components: C - (V - F / 2) / 2 for C components
// (V - F / 2 is V - E + F when every edge has two triangles).
int handleCount(const TriangleSoup& surface);

} // namespace shrinkwrap

#endif
