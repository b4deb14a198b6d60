#include "Distance/WindingSign.h"

#include "Common/Parallel.h"

#include <atomic>
#include <cmath>

namespace shrinkwrap
{

SiteList trustedNormals(const DistanceSource& source, const DistanceBand& band)
{
  // A site is trusted where its pseudonormal is sure and its triangle's sides are confirmed.
  // Untrusted sites get n = 0: the winding number decides.
  const std::vector<char>& confirmed = source.sidesConfirmed();
  const std::size_t nb = band.nodes.size();
  SiteList normal(nb);
  parallelFor(0, static_cast<Index>(nb), [&](Index b, Index e) {
    for (Index k = b; k < e; ++k)
    {
      const int t = band.element[k];
      const bool trusted =
        band.sure[k] && t >= 0 && t < static_cast<int>(confirmed.size()) && confirmed[t];
      normal[k] =
        trusted ? Vec3(band.normal[k][0], band.normal[k][1], band.normal[k][2]) : Vec3::Zero();
    }
  });
  return normal;
}

WindingSignResult signByWindingNumber(const DistanceSource& source, const GridLattice& lattice,
  const SiteList& sitePoints, const SiteList& normal, const std::int32_t* site, std::uint8_t* state,
  const Progress& progress)
{
  WindingSignResult result;
  for (char c : source.sidesConfirmed())
  {
    result.unconfirmed += !c;
  }
  // For every node x whose closest point c is a trusted site's, the side is that of the
  // pseudonormal n at c (Baerentzen & Aanaes: (x - c) . n > 0 outside, whatever the feature), where
  // x is clearly off the plane across n (cos > 0.05: a thin blade's normal cone is almost a half
  // space).
  const auto& d = lattice.dims;
  const double h = lattice.minSpacing();
  std::atomic<long long> evaluated{ 0 }, inside{ 0 };
  result.completed =
    forChunks(static_cast<long long>(d[1]) * d[2], 64, progress, [&](long long b, long long e) {
      long long counted = 0, in = 0;
      for (long long row = b; row < e; ++row)
      {
        const int j = static_cast<int>(row % d[1]), k = static_cast<int>(row / d[1]);
        const std::int64_t first = lattice.index(0, j, k);
        for (int i = 0; i < d[0]; ++i)
        {
          const std::int64_t n = first + i;
          if (state[n] == BandOnSurface)
          {
            continue;
          }
          const Vec3 x = lattice.position(i, j, k);
          const std::int32_t s = site[n];
          bool isInside = false, decided = false;
          if (s >= 0)
          {
            const Vec3 r = x - sitePoints[s];
            const double height = normal[s].dot(r);
            decided = std::abs(height) > 0.05 * r.norm() && std::abs(height) > 1e-9 * h;
            isInside = height < 0;
          }
          if (!decided)
          {
            isInside = std::abs(source.windingNumber(x)) > 0.5;
            ++counted;
          }
          in += isInside;
          state[n] = isBand(state[n]) ? (isInside ? BandInside : BandOutside)
                                      : (isInside ? Inside : Outside);
        }
      }
      evaluated += counted;
      inside += in;
    });
  result.evaluated = evaluated;
  result.inside = inside;
  return result;
}

} // namespace shrinkwrap
