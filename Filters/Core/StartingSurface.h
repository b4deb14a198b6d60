// Preparing a caller's starting surface. The paper's Section 5 proposes starting from a contour of d
// "after tangentially relaxing triangle vertices", which also keeps the target's holes open. A
// marching-cubes contour needs two repairs first:
// - specks, closed components around single grid nodes, which mean curvature shrinks to a point;
// - slivers and near-coincident vertices, which fail the evolution's degenerate-triangle check at once.
#ifndef ShrinkWrap_StartingSurface_h
#define ShrinkWrap_StartingSurface_h

#include "EdgeFlips.h"
#include "Icosphere.h"
#include "SurfaceMesh.h"

#include <string>

namespace shrinkwrap
{

// Removes the connected components whose bounding box is smaller than `size` along every axis;
// returns how many were removed.
int removeSpecks(TriangleSurface& surface, double size);

// Removes the components that face the other way from the largest one: the walls of cavities, which
// a contour of an unsigned field has inside the target. Returns how many were removed.
int removeCavities(TriangleSurface& surface);

struct RelaxSettings
{
  int iterations = 10;
  double weight = 0.5; // share of the way to the tangential centroid per iteration
  FlipSettings flips;
};

// Each iteration moves every vertex part of the way to the centroid of its neighbours within its
// tangent plane, then flips edges (EdgeFlips.h): the shape stays, the triangles even out. The result
// is a new mesh (its initial points are the relaxed positions) in `relaxed`; false with a message if
// the flips left no closed 2-manifold (they should not).
bool relaxTangentially(
  const SurfaceMesh& mesh, const RelaxSettings& settings, SurfaceMesh& relaxed, std::string& error);

} // namespace shrinkwrap

#endif
