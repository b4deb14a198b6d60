// Edge collapses for triangles that degenerate where the surface is compressed (a fold forming as
// it sinks into a concave pocket). Flips (EdgeFlips.h) mend caps, whose third vertex lies on the
// long edge, but not needles, whose short edge shrinks to nothing; a collapse merges the two ends
// of such an edge at its midpoint. It removes one vertex and two triangles and keeps the surface a
// closed 2-manifold of the same genus (the link condition).
#ifndef ShrinkWrap_EdgeCollapses_h
#define ShrinkWrap_EdgeCollapses_h

#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct CollapseSettings
{
  double maxAngle =
    0.1; // radians: triangles with a smaller angle have their shortest edge collapsed
  double minNormalDot =
    0.5;              // every triangle around the merged vertex keeps its normal within 60 degrees
  int maxPasses = 10; // passes per step (the evolver's)
  bool avoidCrossings =
    true; // no collapse whose new triangles would cross the surface (CrossingGuard)
  // A triangle around the edge with an angle under maxAngle has no normal to keep: true, what it
  // turns into must face the way the area-weighted normal of the fan does. Marching cubes' slivers
  // on a contour (the offset start) otherwise turn over, the surface crosses itself there, and the
  // coarsening is redone with guards (10 of 12 starts measured; 2 with it). Off in the evolution,
  // whose steps seldom cross (and where it was measured to change nothing of that).
  bool orientDegenerate = false;
  std::vector<Box>
    guardOnlyIn; // not empty: avoidCrossings checks only the collapses within these boxes
};

// The vertex property (double) that marks the vertices collapses keep in place (> 0; the larger,
// the firmer), e.g. those holding a target's rim (RimCoverage.h): an edge with such an end merges
// into it, not at its midpoint.
constexpr const char* kAnchor = "v:anchor";

struct Merge
{
  int keep, gone;
  Vec3 at;
};
// How edge (a, b) merges: into the firmer anchored end, at its position; without anchors (`anchors`
// empty or 0 at both ends), a keeps and the two meet at the midpoint.
Merge mergeOf(const std::vector<Vec3>& x, const std::vector<double>& anchors, int a, int b);

// Calls f(v, u, w) for every triangle (v, u, w) around a or b (v in {a, b}) other than the two on
// the edge (a, b): the triangles that merging a and b turns into (m, u, w).
template <typename F>
void forEachFanTriangle(const SurfaceMesh& mesh, int a, int b, F&& f)
{
  for (int v : { a, b })
  {
    for (int p = mesh.ringBegin(v); p < mesh.ringEnd(v); ++p)
    {
      const int u = mesh.ring(p), w = mesh.ring(mesh.next(v, p));
      if (u != a && u != b && w != a && w != b)
      {
        f(v, u, w);
      }
    }
  }
}

// Whether merging `gone` into `keep` at m keeps a closed 2-manifold of the same genus with the
// orientations kept: the two vertices opposite the edge keep valence above 3, the merged vertex has
// at least 3, only those two are neighbours of both (link condition), and no other triangle around
// them turns by more than the settings allow. (keep, gone) must be an edge; the rings must be
// current around both.
bool collapseIsOk(const SurfaceMesh& mesh, const std::vector<Vec3>& x, int keep, int gone,
  const Vec3& m, const CollapseSettings& settings);

// One collapse of a pass: merges `gone` into `keep` at m unless either was touched by an earlier
// collapse of the pass, collapseIsOk fails or (with avoidCrossings) the pass's guard finds the new
// triangles crossing the surface; then marks both and their neighbours touched, so that every ring
// the pass reads is current (x: the positions before the pass), and tells the guard. True if it
// collapsed.
bool collapseInPass(SurfaceMesh& mesh, const std::vector<Vec3>& x, int keep, int gone,
  const Vec3& m, const CollapseSettings& settings, std::vector<char>& touched,
  CrossingGuard& guard);

// One pass over the triangles of `mesh` (a vertex takes part in at most one collapse), committed:
// the vertex data of a merged pair is the kept vertex's. Returns the number of collapses.
int collapseEdges(SurfaceMesh& mesh, const CollapseSettings& settings);

} // namespace shrinkwrap

#endif
