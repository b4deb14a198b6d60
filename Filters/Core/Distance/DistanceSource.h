// What Algorithm 1 needs of a surface, as an interface: its bounds, the grid cells it touches (the
// box-overlap query behind the outline), and for a point the nearest surface point with the side
// the point is on (the closest-point query behind the band). Triangles implement it
// (TriangleSource: the welded soup, its AABB tree, its pseudonormals, its octree outline); a point
// set implements it without sides (PointSource: the nearest point; PointSurface: the surface fitted
// to the points). Where the sides of a surface are in doubt (holes, crossings, overlaps), its
// generalized winding number decides (WindingSign.h).
#ifndef ShrinkWrap_DistanceSource_h
#define ShrinkWrap_DistanceSource_h

#include "Common/Progress.h"
#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Distance/DistanceGrid.h"
#include "Distance/GridLattice.h"
#include "Distance/PseudoNormals.h"
#include "Distance/WindingNumber.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace shrinkwrap
{

struct SourcePoint
{
  bool found = false; // false: nothing within the search radius
  double squaredDistance = std::numeric_limits<double>::infinity();
  Vec3 point = Vec3::Zero();
  double side = 0; // > 0 outside, < 0 inside (the query point against the surface's normal there)
  Vec3 normal =
    Vec3::Zero();   // that normal: the pseudonormal of the feature the nearest point lies on
  int element = -1; // the triangle (or point) the nearest point lies on
  // false where `side` may be wrong: the nearest point lies on an edge or corner of a hole's rim or
  // of an edge with more than two triangles, or on a triangle without a normal
  bool sure = true;
  // How far a caller may trust this point over its own estimate, 0 to 1 (below 1 where a fitted
  // surface fades out, PointSurface.h), so that switching between them leaves no step.
  double trust = 1;
  // Taken only where it lies beyond the caller's own estimate (farther from the query, signed),
  // never short of it: a noisy cloud's first layer (PointSurface::firstLayer) deepens a closed
  // field only.
  bool beyondEstimate = false;
};

// The nearest point of an AABB tree's hit (not found when the tree found nothing); the side, normal
// and sureness are the source's to add.
SourcePoint nearestOf(const ClosestHit& hit);

class DistanceSource
{
public:
  virtual ~DistanceSource() = default;
  virtual Box bounds() const = 0;
  // The grid cells the surface touches; false if progress asked to stop.
  virtual bool outline(
    const GridLattice& lattice, const Progress& progress, IndexList& cells) const = 0;
  // The nearest surface point to x within sqrt(maxSquaredDistance).
  virtual SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const = 0;

  // The generalized winding number at x (about 1 inside, 0 outside; NaN: this source has none).
  virtual double windingNumber(const Vec3&) const
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Per element, whether the winding number confirms its sides: outside in front, inside behind
  // (false for a triangle inside another part of the surface, or crossing one). Built once, on the
  // first call; empty: no winding number.
  virtual const std::vector<char>& sidesConfirmed() const
  {
    static const std::vector<char> none;
    return none;
  }
  // The edges a wrap must cover (RimCoverage.h), each as its two ends: where the surface ends (a
  // hole's rim, an open sheet's edge) and its sharp creases, where the faces on the two sides turn
  // by more than creaseAngle degrees (180: none). None for points.
  virtual std::vector<std::array<Vec3, 2>> rims(double /*creaseAngle*/) const { return {}; }
  // The triangles measured, welded (null: none, points only).
  virtual const TriangleSoup* triangles() const { return nullptr; }
};

class TriangleSource : public DistanceSource
{
public:
  // Points with identical coordinates are welded first, so that shared vertices and edges have
  // their pseudonormals, and triangles facing against their neighbours are turned
  // (ConsistentOrientation.h).
  explicit TriangleSource(const TriangleSoup& soup);
  Box bounds() const override { return this->Soup.bounds(); }
  bool outline(
    const GridLattice& lattice, const Progress& progress, IndexList& cells) const override;
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  long long boundaryEdges() const { return this->Normals.boundaryEdges(); }
  long long nonManifoldEdges() const { return this->Normals.nonManifoldEdges(); }
  long long reorientedTriangles() const { return this->Reoriented; }
  double windingNumber(const Vec3& x) const override;
  const std::vector<char>& sidesConfirmed() const override;
  // Edges of one triangle (welded), and edges of two whose normals differ by more than creaseAngle.
  std::vector<std::array<Vec3, 2>> rims(double creaseAngle) const override;
  const TriangleSoup* triangles() const override { return &this->Soup; }
  // The index in the soup it was made of of one of its triangles (SourcePoint::element).
  int inputTriangle(int element) const
  {
    return this->Kept.empty() || element < 0 ? element : this->Kept[element];
  }
  // Whether the triangles face into what `field` signs inside: a vote, over up to a few thousand
  // triangles, of the field's side one cell along each normal against one cell against it.
  bool facesInward(const DistanceGrid& field) const;

private:
  const WindingNumber& winding() const;

  long long Reoriented = 0; // before Soup: set while Soup is made
  std::vector<int> Kept;    // inputTriangle() (empty: every triangle kept); set while Soup is made
  TriangleSoup Soup;
  AABBTree Tree;
  PseudoNormals Normals;
  // Built on first use (the sign of a clean closed mesh never needs them).
  mutable std::once_flag WindingBuilt, SidesBuilt;
  mutable std::unique_ptr<WindingNumber> Winding;
  mutable std::vector<char> Sides;
};

} // namespace shrinkwrap

#endif
