// Isotropic remeshing of an evolving surface towards a target edge length L (the groundwork of
// issue #10's adaptive remeshing; after Botsch & Kobbelt 2004 and pmp-library's remeshing): split
// edges longer than 4/3 L, collapse edges shorter than 4/5 L where that makes no edge longer than
// 4/3 L, flip edges towards valence 6, relax tangentially. Every step is a pass of SurfaceMesh
// edits, so positions and vertex data (the evolver's velocities) follow. It does not project onto a
// reference surface: in the evolution the flow itself moves the vertices.
#ifndef ShrinkWrap_Remesher_h
#define ShrinkWrap_Remesher_h

#include "Common/Status.h"
#include "Remeshing/EdgeCollapses.h"
#include "Remeshing/EdgeFlips.h"
#include "Surface/SurfaceMesh.h"

#include <functional>

namespace shrinkwrap
{

struct RemeshSettings
{
  double targetLength = 0;          // L, in the surface's units (> 0)
  double splitAbove = 4.0 / 3.0;    // edges longer than this times L are split
  double collapseBelow = 4.0 / 5.0; // edges shorter than this times L are collapsed
  int iterations = 5;
  double relaxWeight = 0.5;   // share of the way to the tangential centroid; 0: no relaxation
  FlipSettings flips;         // the dihedral guard of every flip
  CollapseSettings collapses; // the normal and crossing guards of every collapse
  // Adaptive sizing: each vertex gets the edge length whose chord stays within chordError * L of a
  // circle of the surface's largest curvature there (pmp-library's sqrt(6 e r - 3 e^2)), between
  // shortest * L and longest * L; an edge's length is the mean of its ends'. shortest = longest =
  // 1: uniform L.
  double shortest = 1, longest = 1, chordError = 0.05, grading = 0.3;
  // Asked between the passes, if set: true stops the remeshing there (the surface stays a valid,
  // partly remeshed one).
  std::function<bool()> stop;
  bool adaptive() const { return this->shortest < 1 || this->longest > 1; }
};

// The vertex property (double) that holds each vertex's edge length in units of L while the
// remeshing runs.
constexpr const char* kEdgeSize = "v:edgeSize";
// Sets kEdgeSize from the surface's curvature: the largest normal curvature towards a neighbour,
// 2 |n . (x_j - x_i)| / |x_j - x_i|^2.
void assignEdgeSizes(SurfaceMesh& mesh, const RemeshSettings& settings);

struct RemeshReport
{
  int splits = 0, collapses = 0, flips = 0;
  Status status;
};

// With kEdgeSize on the mesh, the lengths below are those of an edge of size 1, scaled per edge.
// Splits every edge longer than maxLength at its midpoint, in passes until none is left (at most
// 16). `stop` (StopPoll) ends the passes early, with the edits made so far committed.
int splitLongEdges(SurfaceMesh& mesh, double maxLength, const std::function<bool()>& stop = {});
// Collapses edges shorter than minLength into their midpoints (into an anchored end: kAnchor,
// EdgeCollapses.h) where no edge then exceeds maxLength and collapseInPass allows it, in passes
// until none is left (at most 16); `stop` as for splitLongEdges.
int collapseShortEdges(SurfaceMesh& mesh, double minLength, double maxLength,
  const CollapseSettings& settings, const std::function<bool()>& stop = {});
// One pass of flips that bring the four valences of an edge's triangles closer to 6, within the
// dihedral guard, leaving out those that flipEdges would flip back (flipGainsAngle of the new
// edge); `stop` as for splitLongEdges.
int equalizeValences(
  SurfaceMesh& mesh, const FlipSettings& settings, const std::function<bool()>& stop = {});

RemeshReport remesh(SurfaceMesh& mesh, const RemeshSettings& settings);

} // namespace shrinkwrap

#endif
