// The generalized winding number of a triangle soup (Jacobson, Kavan & Sorkine-Hornung 2013): the
// solid angle the triangles subtend at a point, over 4 pi. About 1 inside a closed outward-facing
// surface and 0 outside, and still so where the surface crosses itself, overlaps, has flipped
// pieces or small holes: inside is where it exceeds 1/2. Evaluated fast after Barill et al., "Fast
// Winding Numbers for Soups and Clouds" (SIGGRAPH 2018): a bounding-volume hierarchy whose nodes
// carry the dipole of their triangles (area-weighted normal at the area-weighted centre); a node
// seen from farther than `accuracy` times its radius counts as its dipole, nearer ones open up, and
// leaves sum exact solid angles (Van Oosterom & Strackee 1983). The hierarchy is the closest-point
// query's (AABBTree.h), with the moments added bottom up.
#ifndef ShrinkWrap_WindingNumber_h
#define ShrinkWrap_WindingNumber_h

#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

struct WindingNumberSettings
{
  // beta: far-field distance in node radii (larger: more exact, slower). At 3 the value is within
  // about 0.02 of the exact sum (TestWindingSign).
  double accuracy = 3;
};

class WindingNumber
{
public:
  // Over the hierarchy of `tree`, built for `soup`.
  WindingNumber(
    const TriangleSoup& soup, const AABBTree& tree, const WindingNumberSettings& settings = {});
  // With a tree of its own.
  explicit WindingNumber(const TriangleSoup& soup, const WindingNumberSettings& settings = {});

  // The winding number at x, leaving out triangle `skip` (e.g. the one x lies on; -1: none), with
  // the settings' accuracy or the one given.
  double at(const Vec3& x, int skip = -1, double accuracy = 0) const;
  // The same by summing every triangle's solid angle: the reference the tests compare with.
  double exactAt(const Vec3& x) const;

private:
  struct Node
  {
    Vec3 center;   // area-weighted centroid of the node's triangles
    Vec3 dipole;   // sum of the triangles' area vectors (area times unit normal)
    double area;   // of the node's triangles
    double radius; // of a ball about center that holds every corner
    int first;     // leaf: first slot in Order; inner: left child (right = first + 1)
    int count;     // leaf: triangles; inner: 0
  };
  void moments(int index, const HierarchyNodes& tree);
  double solidAngle(int triangle, const Vec3& x) const;

  std::vector<std::array<Vec3, 3>> Corners;
  std::vector<Node> Nodes;
  std::vector<int> Order;
  WindingNumberSettings Settings;
};

} // namespace shrinkwrap

#endif
