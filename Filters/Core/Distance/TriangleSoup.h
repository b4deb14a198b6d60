// The paper's triangle soup (Section 2.1): indexed triangles with no topology required, so
// non-manifold and duplicate-point meshes are accepted. Points with identical coordinates are welded
// so that the pseudonormals of shared vertices and edges can be found.
#ifndef ShrinkWrap_TriangleSoup_h
#define ShrinkWrap_TriangleSoup_h

#include "IndexedTriangles.h"

namespace shrinkwrap
{

using TriangleSoup = IndexedTriangles;

// Merge points with bit-identical coordinates. The result is the same surface; only the indices
// change (a triangle that then repeats an index is kept: as a segment it still has distances).
TriangleSoup weldDuplicatePoints(const TriangleSoup& soup);

} // namespace shrinkwrap

#endif
