// Rims of open sheets (a hole's edge, a fin, a CAD part's open shell) must stay inside the wrap.
// The wrap folds around such a rim with a layer on each side of the sheet; once both layers lie on
// the sheet (d = 0), nothing in eq. (4) pulls the fold back out to the rim, while the curvature
// term and the remeshing's collapses pull it in, and the rim pokes out. So after each step, the
// points of the target's rims that lie outside the surface pull the nearest triangle onto them, and
// during the step's remeshing the vertices that hold them stay in place.
#ifndef ShrinkWrap_RimCoverage_h
#define ShrinkWrap_RimCoverage_h

#include "Surface/SurfaceMesh.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct RimSettings
{
  bool cover = true;
  double spacing =
    1; // between samples along a rim, in target edge lengths L (L / 2: as close, slower)
  double tolerance = 0.02; // a sample this close to the surface (in L) counts as covered
  double reach = 1.5;      // samples farther from the surface than this (in L) are left alone
  double hold = 0.1; // vertices of a sample's nearest point this close (in L) stay in collapses
  // Sharp creases count as rims where the target's faces turn by more than this (degrees; 180:
  // none), so that the wrap keeps a CAD part's edges and corners, with more vertices.
  double creaseAngle = 180;
};

// Points along the rims, at most `spacing` apart, both ends of every rim edge among them.
std::vector<Vec3> rimSamples(const std::vector<std::array<Vec3, 2>>& rims, double spacing);

// Per vertex of `mesh`, the move that brings the nearest surface point of every sample outside the
// surface, farther than `tolerance` and nearer than `reach`, onto the sample: the nearest
// triangle's corners move by their barycentric share (the largest move wins at a vertex); zero
// elsewhere. Outside: in front of the pseudonormal of the nearest feature.
std::vector<Vec3> rimMoves(
  const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double tolerance, double reach);

// Per vertex of `mesh`, how firmly it holds the samples (kAnchor): the largest barycentric
// weight it has in the nearest surface point of a sample within `reach`; 0 where it holds none. The
// remeshing keeps such vertices in place (kAnchor, EdgeCollapses.h): merging a fold's vertex on
// a rim with its neighbour at the edge's midpoint pulled the fold off the rim by most of an edge
// every step, and the layers on both sides of the sheet then lay too close to move it back.
std::vector<double> rimHolds(
  const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double reach);

} // namespace shrinkwrap

#endif
