// The surface an evolution starts from (Algorithm 3's F(0)): a geodesic icosphere around the
// target, the paper's Section 5 offset surface (a contour of d near the target), or the caller's
// own; then made ready: specks removed, outward oriented, relaxed where it is a contour.
#ifndef ShrinkWrap_StartingSurface_h
#define ShrinkWrap_StartingSurface_h

#include "Common/Progress.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/ContourTopology.h"
#include "Distance/DistanceGrid.h"
#include "Remeshing/EdgeFlips.h"
#include "Surface/SurfaceMesh.h"

#include <functional>
#include <limits>
#include <optional>

namespace shrinkwrap
{

enum class StartShape
{
  Icosphere,
  OffsetSurface
};

struct StartSettings
{
  StartShape shape = StartShape::OffsetSurface;
  int subdivision = 3; // s, the icosphere's level (642 vertices)
  double offset = 3;   // the offset surface's distance from the closed target, cells of the field
  double maxOffset = std::numeric_limits<double>::infinity(); // ... at most this (field units), at
                                                              // least one cell
  int relaxation = 10; // tangential relaxation iterations of a contour or a given surface
  // A contour start is first coarsened by collapses to this edge length (field units; checked for
  // crossings, CheckedEdits.h), so that its relaxation and the first step handle the vertices the
  // wrap will have; unset: kept as the contour made it.
  std::optional<double> coarsenTo;
};

// The paper's Section 5 start, a contour of d at `offset` (in the field's units) from the target.
// Give it the field of the target's closing (GapClosing.h): a contour of the target's own field
// nearly touches itself where two parts are about twice the offset apart, and the thin necks
// marching cubes leaves there pinch off under curvature at once. Walls of cavities (an unsigned
// field's contour has them inside an open target) are left out.
Status offsetSurface(
  const DistanceGrid& field, double offset, const Contour& contour, TriangleSoup& surface);

// Outward orientation, which eta N with D > 0 and the output's normals and curvatures rely on.
Status orientOutwards(SurfaceMesh& mesh);

// The starting surface, ready to evolve: `given` if not null, else the shape of `settings` (the
// icosphere around `targetBox`, or the offset surface of `field`, which should be the closing's);
// specks smaller than two cells of the field removed (counted in `specks`), outward oriented, and a
// contour or a given surface relaxed with `flips`. Fails "aborted" when `progress` asks to stop.
Status startingSurface(const DistanceGrid& field, const Box& targetBox, const TriangleSoup* given,
  const StartSettings& settings, const FlipSettings& flips, const Contour& contour,
  SurfaceMesh& mesh, int& specks, const Progress& progress = Progress());

} // namespace shrinkwrap

#endif
