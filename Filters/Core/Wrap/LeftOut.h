// The parts of a target that a wrap leaves out: connected pieces of the target's triangles that lie
// wholly outside the wrap and farther than a margin from it (grains smaller than the wrap's edges
// and farther than the Gap Size from the rest, say), so that the output can say what it left out.
#ifndef ShrinkWrap_LeftOut_h
#define ShrinkWrap_LeftOut_h

#include "Common/TriangleSoup.h"

namespace shrinkwrap
{

struct LeftOutParts
{
  long long parts = 0;   // connected pieces of the target (triangles sharing a corner index)
  long long leftOut = 0; // of them, wholly outside the wrap and farther than the margin from it
};

// `target` welded (shared corners by index), `wrap` a closed outward-facing surface; `margin` in
// target units. A target of one part is its wrap's (none left out, nothing measured).
LeftOutParts leftOutParts(const TriangleSoup& target, const TriangleSoup& wrap, double margin);

} // namespace shrinkwrap

#endif
