// Edge flips that raise the smallest angle of a triangle pair, for a Lagrangian surface whose fixed
// connectivity cannot follow large tangential stretching (the paper's Section 5 names connectivity
// adjustments as the missing piece). A flip keeps the vertices, so the surface stays closed and
// 2-manifold; it is refused where the two triangles are not nearly coplanar, so the shape is kept,
// and where the new triangles would cross another part of the surface.
#ifndef ShrinkWrap_EdgeFlips_h
#define ShrinkWrap_EdgeFlips_h

#include "Common/Box.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"

#include <array>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace shrinkwrap
{

struct FlipSettings
{
  double maxDihedral = 60;    // degrees between the normals of the two triangles, before and after
  double minGain = 0.01;      // radians the smallest angle of the pair must gain
  bool avoidCrossings = true; // no flip whose new triangles would cross the surface (CrossingGuard)
  std::vector<Box>
    guardOnlyIn; // not empty: avoidCrossings checks only the flips within these boxes
};

// Whether flipping edge (i, j) of triangles (i, j, c) and (i, d, j) to (c, d) keeps the shape: both
// pairs of triangles within the dihedral limit (cosMax, the cosine of maxDihedral) and the new
// triangles facing the way the old ones did.
bool flipKeepsShape(const std::vector<Vec3>& x, int i, int j, int c, int d, double cosMax);

// Whether flipping edge (i, j) of triangles (i, j, c) and (i, d, j) to (c, d) raises the pair's
// smallest angle by at least minGain (radians): the test of flipEdges, before its checks of shape
// and crossings.
bool flipGainsAngle(const std::vector<Vec3>& x, int i, int j, int c, int d, double minGain);

// One pass of flips, decided from the surface as the pass began (the rings stay so until the
// commit): a vertex takes part in at most one flip, and a flip is refused that would leave a vertex
// of valence 3 or less, pinch the surface, change its shape or cross it.
class FlipPass
{
public:
  FlipPass(const SurfaceMesh& mesh, const FlipSettings& settings);
  // Whether edge (i, j), c and d the far corners of its triangles, may flip before the shape and
  // crossing checks: no end touched yet, both ends of valence above 3.
  bool free(const SurfaceMesh& mesh, int i, int j, int c, int d) const;
  // Flips (i, j) to (c, d) where it keeps the shape and crosses nothing; true when it did.
  bool flip(SurfaceMesh& mesh, int i, int j, int c, int d);
  const std::vector<Vec3>& points() const { return this->X; }
  // Asked within the crossing guard's build (CrossingGuard::setStop).
  void setStop(std::function<bool()> stop) { this->Guard.setStop(std::move(stop)); }
  int flips() const { return this->Flips; }

private:
  const FlipSettings& Settings;
  const std::vector<Vec3>& X;
  double CosMax;
  std::vector<std::array<int, 3>> Triangles; // as the pass began: flips change the mesh's own
  CrossingGuard Guard;
  std::vector<char> Touched;
  int Flips = 0;
};

// One pass of flips over the edges of `mesh` (a vertex takes part in at most one flip; the evolver
// runs a pass after every step), committed. Returns the number of flips. `stop` (empty: never),
// polled within the pass (StopPoll), ends it early with the flips made so far.
int flipEdges(
  SurfaceMesh& mesh, const FlipSettings& settings, const std::function<bool()>& stop = {});

} // namespace shrinkwrap

#endif
