// Edge collapses for triangles that degenerate where the surface is compressed (a fold forming as it
// sinks into a concave pocket). Flips (EdgeFlips.h) mend caps, whose third vertex lies on the long
// edge, but not needles, whose short edge shrinks to nothing; a collapse merges the two ends of such
// an edge at its midpoint. It removes one vertex and two triangles and keeps the surface a closed
// 2-manifold of the same genus (the link condition).
#ifndef ShrinkWrap_EdgeCollapses_h
#define ShrinkWrap_EdgeCollapses_h

#include "SurfaceMesh.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct CollapseSettings
{
  double maxAngle = 0.1;     // radians: triangles with a smaller angle have their shortest edge collapsed
  double minNormalDot = 0.5; // every triangle around the merged vertex keeps its normal within 60 degrees
  int maxPasses = 10;        // passes per step (the evolver's)
};

// One pass over the triangles of `mesh` at positions `x` (a vertex takes part in at most one collapse).
// Returns the number of collapses and the new surface in `points` and `triangles`; `kept` maps every
// new vertex to the old one it continues (for per-vertex data). With no collapse the outputs are
// untouched.
int collapseEdges(const SurfaceMesh& mesh, const std::vector<Vec3>& x, const CollapseSettings& settings,
  std::vector<Vec3>& points, std::vector<std::array<int, 3>>& triangles, std::vector<int>& kept);

} // namespace shrinkwrap

#endif
