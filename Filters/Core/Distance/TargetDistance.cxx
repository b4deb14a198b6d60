#include "Distance/TargetDistance.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

TargetDistance::TargetDistance(
  DistanceGrid grid, std::shared_ptr<const DistanceSource> exact, double exactBand, bool isSigned)
  : Grid(std::move(grid))
  , Exact(std::move(exact))
  , Signed(isSigned)
{
  this->Cell = this->Grid.empty() ? 1.0 : this->Grid.lattice().spacing.maxCoeff();
  this->Band = std::max(exactBand, 0.0) * this->Cell;
}

DistanceSample TargetDistance::sample(const Vec3& x) const
{
  const DistanceSample far = this->Grid.sample(x);
  const double reach = this->Band + this->Cell;
  if (!this->Exact || !(std::abs(far.value) < reach))
  {
    return far;
  }
  // The grid's error is below a cell, so the closest point lies within reach + one cell.
  const SourcePoint p = this->Exact->closestPoint(x, (reach + this->Cell) * (reach + this->Cell));
  if (!p.found)
  {
    return far;
  }
  const double distance = std::sqrt(p.squaredDistance);
  // The side: the grid's sign where it is clear (its votes survive a dirty target), the target's
  // pseudonormal at the closest point within half a cell of it; a source without sides (a point
  // set's fitted surface) is oriented by the grid's gradient.
  double sign = 1;
  if (this->Signed && p.side == 0)
  {
    sign = (x - p.point).dot(far.gradient) < 0 ? -1.0 : 1.0;
  }
  else if (this->Signed)
  {
    const double side = this->Inward ? -p.side : p.side;
    sign = std::abs(far.value) > 0.5 * this->Cell ? (far.value < 0 ? -1.0 : 1.0)
                                                  : (side < 0 ? -1.0 : 1.0);
  }
  DistanceSample near;
  near.value = sign * distance;
  near.gradient =
    distance > 1e-9 * this->Cell ? Vec3(sign * (x - p.point) / distance) : far.gradient;
  if (p.beyondEstimate &&
    near.value < far.value) // a noisy cloud's first layer only deepens the closing
  {
    return far;
  }
  const double w = std::clamp((reach - std::abs(far.value)) / this->Cell, 0.0, 1.0) *
    std::clamp(p.trust, 0.0, 1.0);
  if (w >= 1)
  {
    return near;
  }
  DistanceSample blended;
  blended.value = w * near.value + (1 - w) * far.value;
  blended.gradient = w * near.gradient + (1 - w) * far.gradient;
  return blended;
}

} // namespace shrinkwrap
