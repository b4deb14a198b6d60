#include "Distance/DistanceGrid.h"

#include "Common/Parallel.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

DistanceSample DistanceGrid::sample(const Vec3& x) const
{
  const auto& d = this->Lattice.dims;
  int c[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const double t = (x[a] - this->Lattice.origin[a]) / this->Lattice.spacing[a];
    const double u =
      std::isnan(t) ? 0.0 : std::clamp(t, 0.0, d[a] - 1.0); // a NaN point: the evolver reports it
    c[a] = std::min(static_cast<int>(u), d[a] - 2);
    f[a] = u - c[a];
  }
  const std::int64_t sy = d[0], sz = sy * d[1];
  const float* v = this->Values.data() + this->Lattice.index(c[0], c[1], c[2]);
  // Corner values v[ijk] with i, j, k in {0, 1}.
  const double v000 = v[0], v100 = v[1], v010 = v[sy], v110 = v[sy + 1];
  const double v001 = v[sz], v101 = v[sz + 1], v011 = v[sz + sy], v111 = v[sz + sy + 1];
  const double x0 = v000 + f[0] * (v100 - v000), x1 = v010 + f[0] * (v110 - v010);
  const double x2 = v001 + f[0] * (v101 - v001), x3 = v011 + f[0] * (v111 - v011);
  const double y0 = x0 + f[1] * (x1 - x0), y1 = x2 + f[1] * (x3 - x2);
  DistanceSample s;
  s.value = y0 + f[2] * (y1 - y0);
  // Partial derivatives of the same trilinear form.
  const double dx0 = v100 - v000, dx1 = v110 - v010, dx2 = v101 - v001, dx3 = v111 - v011;
  const double dxy0 = dx0 + f[1] * (dx1 - dx0), dxy1 = dx2 + f[1] * (dx3 - dx2);
  s.gradient.x() = (dxy0 + f[2] * (dxy1 - dxy0)) / this->Lattice.spacing[0];
  s.gradient.y() = ((x1 - x0) + f[2] * ((x3 - x2) - (x1 - x0))) / this->Lattice.spacing[1];
  s.gradient.z() = (y1 - y0) / this->Lattice.spacing[2];
  return s;
}

DistanceGrid DistanceGrid::refined() const
{
  const GridLattice& coarse = this->Lattice;
  if (this->empty())
  {
    return *this;
  }
  GridLattice fine = coarse;
  for (int a = 0; a < 3; ++a)
  {
    fine.dims[a] = 2 * (coarse.dims[a] - 1) + 1;
    fine.spacing[a] = coarse.spacing[a] / 2;
  }
  FieldValues values(fine.nodeCount());
  const auto at = [this](
                    int i, int j, int k) { return this->Values[this->Lattice.index(i, j, k)]; };
  parallelFor(0, fine.dims[2], 1, [&](Index kb, Index ke) {
    for (int k = static_cast<int>(kb); k < ke; ++k)
    {
      for (int j = 0; j < fine.dims[1]; ++j)
      {
        float* row = values.data() + fine.index(0, j, k);
        for (int i = 0; i < fine.dims[0]; ++i)
        {
          row[i] = halfSpacingValue(at, i, j, k);
        }
      }
    }
  });
  return DistanceGrid(fine, std::move(values));
}

} // namespace shrinkwrap
