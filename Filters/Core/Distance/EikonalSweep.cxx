#include "Distance/EikonalSweep.h"
#include "Common/Parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shrinkwrap
{

namespace
{
// Godunov update for |grad u| = 1 from the smaller neighbour on each axis (a) with spacings h:
// the largest u with sum_k max(u - a_k, 0)^2 / h_k^2 = 1.
float eikonalUpdate(std::array<double, 3> a, std::array<double, 3> h)
{
  // Sort axes by neighbour value.
  for (int x = 0; x < 2; ++x)
  {
    for (int y = 0; y < 2 - x; ++y)
    {
      if (a[y] > a[y + 1])
      {
        std::swap(a[y], a[y + 1]);
        std::swap(h[y], h[y + 1]);
      }
    }
  }
  double u = a[0] + h[0];
  double sw = 0, swa = 0, swa2 = 0; // sums of 1/h^2, a/h^2, a^2/h^2
  for (int m = 0; m < 3; ++m)
  {
    if (!std::isfinite(a[m]) || (m > 0 && u <= a[m]))
    {
      break;
    }
    const double w = 1 / (h[m] * h[m]);
    sw += w;
    swa += w * a[m];
    swa2 += w * a[m] * a[m];
    const double disc = swa * swa - sw * (swa2 - 1);
    u = disc >= 0 ? (swa + std::sqrt(disc)) / sw : u;
  }
  return static_cast<float>(u);
}
} // namespace

bool sweepEikonal(const GridLattice& lattice, const std::uint8_t* frozen, float* distance,
  int iterations, const Progress& progress)
{
  const auto& d = lattice.dims;
  const std::int64_t sy = d[0], sz = sy * d[1];
  const std::array<double, 3> h = { lattice.spacing[0], lattice.spacing[1], lattice.spacing[2] };
  const float inf = std::numeric_limits<float>::infinity();
  for (std::int64_t n = 0; n < lattice.nodeCount(); ++n)
  {
    if (!frozen[n])
    {
      distance[n] = inf;
    }
  }
  auto neighbourMin = [&](std::int64_t n, int i, int len, std::int64_t stride) -> double {
    const float lo = i > 0 ? distance[n - stride] : inf;
    const float hi = i + 1 < len ? distance[n + stride] : inf;
    return std::min(lo, hi);
  };
  const int sweeps = 8 * std::max(1, iterations);
  for (int s = 0; s < sweeps; ++s)
  {
    const int o = s % 8;
    const int di = (o & 1) ? -1 : 1, dj = (o & 2) ? -1 : 1, dk = (o & 4) ? -1 : 1;
    for (int k = dk > 0 ? 0 : d[2] - 1; k >= 0 && k < d[2]; k += dk)
    {
      for (int j = dj > 0 ? 0 : d[1] - 1; j >= 0 && j < d[1]; j += dj)
      {
        for (int i = di > 0 ? 0 : d[0] - 1; i >= 0 && i < d[0]; i += di)
        {
          const std::int64_t n = lattice.index(i, j, k);
          if (frozen[n])
          {
            continue;
          }
          const std::array<double, 3> a = { neighbourMin(n, i, d[0], 1),
            neighbourMin(n, j, d[1], sy), neighbourMin(n, k, d[2], sz) };
          if (std::isfinite(std::min({ a[0], a[1], a[2] })))
          {
            distance[n] = std::min(distance[n], eikonalUpdate(a, h));
          }
        }
      }
    }
    if (!progress.report(static_cast<double>(s + 1) / sweeps))
    {
      return false;
    }
  }
  return true;
}

} // namespace shrinkwrap
