#include "Distance/GridLattice.h"

#include <cmath>
#include <limits>

namespace shrinkwrap
{

namespace
{
// Node counts beyond this per axis overflow the 32-bit indices VTK extents use.
constexpr double kMaxNodesPerAxis = 1 << 30;
} // namespace

bool withinCoordinateRange(const Box& box)
{
  return box.min.cwiseAbs().maxCoeff() <= kLargestCoordinate &&
    box.max.cwiseAbs().maxCoeff() <= kLargestCoordinate;
}

Status placeGrid(const Box& meshBounds, const GridPlacement& placement, GridLattice& lattice)
{
  if (meshBounds.empty() || !meshBounds.min.allFinite() || !meshBounds.max.allFinite())
  {
    return Status::failure("the mesh bounds are empty or not finite");
  }
  if (!(placement.boxScale > 0) || !std::isfinite(placement.boxScale))
  {
    return Status::failure("Box Scale must be positive");
  }
  if (!(placement.offsetFactor >= 0) || !std::isfinite(placement.offsetFactor))
  {
    return Status::failure("Offset Factor must be zero or positive");
  }
  if (placement.cellSize < 0 || !std::isfinite(placement.cellSize))
  {
    return Status::failure("Cell Size must be positive (or 0 to use Resolution)");
  }
  if (placement.cellSize == 0 && placement.resolution < 1)
  {
    return Status::failure("Resolution must be at least 1 (cells along the longest axis)");
  }
  const Vec3 scaled = placement.boxScale * meshBounds.size();
  const double offset = placement.offsetFactor * scaled.maxCoeff();
  const Vec3 extent = scaled + Vec3::Constant(2 * offset);
  if (!(extent.maxCoeff() > 0))
  {
    return Status::failure("the input has no extent (all its points coincide)");
  }
  const double h =
    placement.cellSize > 0 ? placement.cellSize : extent.maxCoeff() / placement.resolution;
  lattice.spacing = Vec3::Constant(h);
  Vec3 span;
  for (int a = 0; a < 3; ++a)
  {
    // Whole cells covering the extent (at least one), grown symmetrically about the centre.
    const double cells = std::max(1.0, std::ceil(extent[a] / h - 1e-9));
    if (!(cells < kMaxNodesPerAxis))
    {
      return Status::failure("the grid would have more than 2^30 nodes along an axis");
    }
    lattice.dims[a] = static_cast<int>(cells) + 1;
    span[a] = cells * h;
  }
  lattice.origin = meshBounds.center() - 0.5 * span;
  if (!withinCoordinateRange(lattice.bounds()))
  {
    return Status::failure(
      "the grid would reach beyond coordinates of +-1e30; lower Offset Factor or Box Scale");
  }
  return {};
}

Status explicitGrid(const Box& bounds, const std::array<int, 3>& dims, GridLattice& lattice)
{
  if (!bounds.min.allFinite() || !bounds.max.allFinite() || !withinCoordinateRange(bounds))
  {
    return Status::failure("the output bounds are not finite or beyond +-1e30");
  }
  for (int a = 0; a < 3; ++a)
  {
    if (dims[a] < 2)
    {
      return Status::failure("the output dimensions must be at least 2 nodes on every axis");
    }
    if (!(bounds.max[a] > bounds.min[a]))
    {
      return Status::failure("the output bounds must have max > min on every axis");
    }
    lattice.dims[a] = dims[a];
    lattice.spacing[a] = (bounds.max[a] - bounds.min[a]) / (dims[a] - 1);
  }
  lattice.origin = bounds.min;
  return {};
}

} // namespace shrinkwrap
