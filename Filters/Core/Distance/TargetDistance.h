// The distance to the target that the evolution samples (d and grad d of eqs. (3)-(4)): the grid
// far from the target, and exact near it, from the closest point on the target itself. Trilinear
// interpolation of a grid is off by a fraction of a cell near the surface, so a surface driven by
// it settles no closer than that; the closest point (the AABB tree of Algorithm 1) lets it land on
// the target. Between `exactBand` and `exactBand` + one cell the two are blended, so d stays
// continuous.
#ifndef ShrinkWrap_TargetDistance_h
#define ShrinkWrap_TargetDistance_h

#include "Distance/DistanceGrid.h"
#include "Distance/DistanceSource.h"

#include <memory>

namespace shrinkwrap
{

class TargetDistance
{
public:
  TargetDistance() = default;
  // The grid alone (exact = null), or the grid with the target for the near field, within
  // `exactBand` cells of it. `isSigned`: the grid is signed (else d >= 0 everywhere).
  explicit TargetDistance(DistanceGrid grid, std::shared_ptr<const DistanceSource> exact = nullptr,
    double exactBand = 2, bool isSigned = true);

  const DistanceGrid& grid() const { return this->Grid; }
  bool empty() const { return this->Grid.empty(); }
  DistanceSample sample(const Vec3& x) const;
  // The target itself, where the near field is exact (else null).
  const DistanceSource* exact() const { return this->Exact.get(); }
  const std::shared_ptr<const DistanceSource>& exactShared() const { return this->Exact; }
  // The target's triangles face inwards (TriangleSource::facesInward): the near field takes the
  // side opposite their pseudonormals, as the grid's sign does.
  void setFacesInward(bool inward) { this->Inward = inward; }

private:
  DistanceGrid Grid;
  std::shared_ptr<const DistanceSource> Exact;
  double Band = 0; // in the field's units
  double Cell = 1;
  bool Signed = true;
  bool Inward = false;
};

} // namespace shrinkwrap

#endif
