// A point cloud as a wrap takes it, measured once: its nearest-neighbour spacing (median, and in
// its sparsest part: PointSpacing), and the surface the points sample (PointSurface), which also
// measures their noise.
#ifndef ShrinkWrap_PointCloud_h
#define ShrinkWrap_PointCloud_h

#include "Common/Status.h"
#include "Distance/PointSource.h"
#include "Distance/PointSurface.h"

#include <memory>

namespace shrinkwrap
{

struct PointCloud
{
  std::shared_ptr<const PointSource> points;
  std::shared_ptr<const PointSurface> surface; // none where the spacing is 0
  double spacing = 0;                          // median nearest-neighbour distance, target units
  double sparseSpacing = 0; // the same in the sparsest part; 0 (none) counts as `spacing`
  double noise() const;     // PointSurface::typicalNoise, 0 without a surface
};

// The cloud of `points` measured (checkPoints first: finite, not empty).
PointCloud measureCloud(PointList points);

// Why points cannot be wrapped, if they cannot: they coincide, or lie on a line or in a plane
// (within 1e-6 of their extent), so they enclose nothing.
Status checkPointsEnclose(const PointList& points);

} // namespace shrinkwrap

#endif
