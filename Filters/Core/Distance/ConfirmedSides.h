// Which triangles have outside in front and inside behind, as the generalized winding number tells
// (WindingNumber.h). At a point of a clean surface the rest of it has winding number 1/2: 0 just in
// front, 1 just behind. A triangle inside another part of the surface (an overlap) sees about 3/2
// there: nothing around it is outside. One that crosses another has parts on both sides of it.
// Between crossings the winding number of the rest changes continuously (nothing passes through the
// surface there), so it is sampled per patch: the triangles connected without passing a crossing
// one.
#ifndef ShrinkWrap_ConfirmedSides_h
#define ShrinkWrap_ConfirmedSides_h

#include "Common/TriangleSoup.h"
#include "Distance/WindingNumber.h"

#include <vector>

namespace shrinkwrap
{

// Per triangle of a welded soup: confirmed when the patch it belongs to sees winding number 1/2 +-
// 0.4 at every sample (where a patch does not, its crossing triangles are left out and the rest
// sampled again), and the same holds for every triangle around its corners (a closest point on an
// edge or corner takes the pseudonormal of all of them).
std::vector<char> confirmSides(const TriangleSoup& welded, const WindingNumber& winding);

} // namespace shrinkwrap

#endif
