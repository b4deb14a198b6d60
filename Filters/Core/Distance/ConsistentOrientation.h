// Triangles of one surface that face the other way from their neighbours (a mesh assembled from
// pieces, or half its faces flipped) give the wrong side to every point whose closest feature they
// hold, and cancel in the winding number. Across every edge shared by exactly two triangles, the
// two should run it in opposite directions: each edge-connected piece is made so from a seed, then
// turned as the larger share of its area was given (a consistently inward piece, such as the cavity
// of a hollow part, stays inward).
#ifndef ShrinkWrap_ConsistentOrientation_h
#define ShrinkWrap_ConsistentOrientation_h

#include "Common/TriangleSoup.h"

namespace shrinkwrap
{

// Reverses the triangles of a welded soup that disagree with their piece; returns how many.
// Pieces that cannot be oriented (a Moebius strip) keep the orientation found from their seed.
long long orientConsistently(TriangleSoup& welded);

} // namespace shrinkwrap

#endif
