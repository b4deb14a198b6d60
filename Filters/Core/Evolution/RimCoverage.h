// Rims of open sheets (a hole's edge, a fin, a CAD part's open shell) must stay inside the wrap. The wrap
// folds around such a rim with a layer on each side of the sheet; once both layers lie on the sheet
// (d = 0), nothing in eq. (4) pulls the fold back out to the rim, while the curvature term and the
// remeshing's collapses pull it in, and the rim pokes out (mech-holes-shark: by 2% of the diagonal).
// So after each step, the points of the target's rims that lie outside the surface pull the nearest
// triangle onto them.
#ifndef ShrinkWrap_RimCoverage_h
#define ShrinkWrap_RimCoverage_h

#include "SurfaceMesh.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct RimSettings
{
  bool cover = true;
  double spacing = 1;      // between samples along a rim, in target edge lengths L (L / 2: as close, slower)
  double tolerance = 0.02; // a sample this close to the surface (in L) counts as covered
  double reach = 1.5;      // samples farther from the surface than this (in L) are left alone
};

// Points along the rims, at most `spacing` apart, both ends of every rim edge among them.
std::vector<Vec3> rimSamples(const std::vector<std::array<Vec3, 2>>& rims, double spacing);

// Per vertex of `mesh`, the move that brings the nearest surface point of every sample outside the
// surface, farther than `tolerance` and nearer than `reach`, onto the sample: the nearest triangle's
// corners move by their barycentric share (the largest move wins at a vertex); zero elsewhere. Outside:
// in front of the pseudonormal of the nearest feature.
std::vector<Vec3> rimMoves(const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double tolerance, double reach);

} // namespace shrinkwrap

#endif
