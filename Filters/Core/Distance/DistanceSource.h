// What Algorithm 1 needs of a surface, as an interface: its bounds, the grid cells it touches (the
// box-overlap query behind the outline), and for a point the nearest surface point with the side the
// point is on (the closest-point query behind the band). Triangles implement it (TriangleSource: the
// welded soup, its AABB tree, its pseudonormals, its octree outline); a point set with normals can
// implement it the same way (issue #13) and get the band, sweeps and sign unchanged.
#ifndef ShrinkWrap_DistanceSource_h
#define ShrinkWrap_DistanceSource_h

#include "AABBTree.h"
#include "GridLattice.h"
#include "Progress.h"
#include "PseudoNormals.h"
#include "TriangleSoup.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace shrinkwrap
{

struct SourcePoint
{
  bool found = false; // false: nothing within the search radius
  double squaredDistance = std::numeric_limits<double>::infinity();
  Vec3 point = Vec3::Zero();
  double side = 0; // > 0 outside, < 0 inside (the query point against the surface's normal there)
};

class DistanceSource
{
public:
  virtual ~DistanceSource() = default;
  virtual Box bounds() const = 0;
  // The grid cells the surface touches; false if progress asked to stop.
  virtual bool outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const = 0;
  // The nearest surface point to x within sqrt(maxSquaredDistance).
  virtual SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const = 0;
};

class TriangleSource : public DistanceSource
{
public:
  // Points with identical coordinates are welded first, so that shared vertices and edges have
  // their pseudonormals.
  explicit TriangleSource(const TriangleSoup& soup);
  Box bounds() const override { return this->Soup.bounds(); }
  bool outline(const GridLattice& lattice, const Progress& progress, std::vector<std::int64_t>& cells) const override;
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  long long boundaryEdges() const { return this->Normals.boundaryEdges(); }
  long long nonManifoldEdges() const { return this->Normals.nonManifoldEdges(); }

private:
  TriangleSoup Soup;
  AABBTree Tree;
  PseudoNormals Normals;
};

} // namespace shrinkwrap

#endif
