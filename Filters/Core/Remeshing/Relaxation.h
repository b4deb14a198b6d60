// Tangential relaxation of a starting surface (the paper's Section 5 proposes starting from a
// contour of d "after tangentially relaxing triangle vertices"): a marching-cubes contour has
// slivers and near-coincident vertices that would fail the evolution's degenerate-triangle check at
// once.
#ifndef ShrinkWrap_Relaxation_h
#define ShrinkWrap_Relaxation_h

#include "Remeshing/EdgeFlips.h"
#include "Surface/SurfaceMesh.h"

namespace shrinkwrap
{

struct RelaxSettings
{
  int iterations = 10;
  double weight = 0.5; // share of the way to the tangential centroid per iteration
  FlipSettings flips;
};

// Each iteration moves every vertex part of the way to the centroid of its neighbours within its
// tangent plane, then flips edges (EdgeFlips.h): the shape stays, the triangles even out. `stop`
// (empty: never), asked between the iterations and polled within the flips, ends them early.
void relaxTangentially(
  SurfaceMesh& mesh, const RelaxSettings& settings, const std::function<bool()>& stop = {});

} // namespace shrinkwrap

#endif
