// A closed, oriented triangle surface as indexed triangles (counter-clockwise seen from outside): what
// starting surfaces are made as, before SurfaceMesh checks them and builds their adjacency.
#ifndef ShrinkWrap_TriangleSurface_h
#define ShrinkWrap_TriangleSurface_h

#include "Common/IndexedTriangles.h"

namespace shrinkwrap
{

using TriangleSurface = IndexedTriangles;

} // namespace shrinkwrap

#endif
