// Several distance sources measured as one (a mesh's polygons and its loose points, Mesh
// Signed Distance's Input Geometry "Polygons and Points"): the nearest point of any of them, the
// cells any of them touches. Unsigned: its parts' sides do not make one inside (a point has none),
// so a caller computes no sign from it.
#ifndef ShrinkWrap_UnionSource_h
#define ShrinkWrap_UnionSource_h

#include "Distance/DistanceSource.h"

#include <memory>
#include <vector>

namespace shrinkwrap
{

class UnionSource : public DistanceSource
{
public:
  explicit UnionSource(std::vector<std::shared_ptr<const DistanceSource>> parts);
  Box bounds() const override;
  bool outline(
    const GridLattice& lattice, const Progress& progress, IndexList& cells) const override;
  // The nearest of the parts' nearest points, side 0 and not sure.
  SourcePoint closestPoint(const Vec3& x, double maxSquaredDistance) const override;
  std::vector<std::array<Vec3, 2>> rims(double creaseAngle) const override; // all parts' rims
  const TriangleSoup* triangles() const override; // the first part's that has triangles

private:
  std::vector<std::shared_ptr<const DistanceSource>> Parts;
};

} // namespace shrinkwrap

#endif
