#include "Distance/PointSource.h"

#include "Common/Parallel.h"
#include "Distance/PointGrid.h"
#include "Distance/PointTree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

namespace shrinkwrap
{

PointSource::PointSource(const std::vector<Vec3>& points)
  : PointSource(PointList(points.begin(), points.end()))
{
}

PointSource::PointSource(PointList points)
  : Points(std::move(points))
  , Bounds(Box::around(this->Points))
  , Tree(this->Points)
{
}

bool PointSource::outline(
  const GridLattice& lattice, const Progress& progress, IndexList& cells) const
{
  cells.clear();
  cells.reserve(this->Points.size());
  for (const Vec3& p : this->Points)
  {
    std::array<int, 3> c;
    bool inside = true;
    for (int a = 0; a < 3; ++a)
    {
      const double u = std::floor((p[a] - lattice.origin[a]) / lattice.spacing[a]);
      inside =
        inside && u >= 0 && u <= lattice.dims[a] - 1; // a point on the far face: its last cell
      c[a] =
        static_cast<int>(std::clamp(u, 0.0, static_cast<double>(std::max(lattice.dims[a] - 2, 0))));
    }
    if (inside)
    {
      cells.push_back(lattice.index(c[0], c[1], c[2]));
    }
  }
  // Sorted and each once: through a bitmap of the cells where it is not much larger than the points
  // (a dense cloud: at 200,000 points the sort took a fifth of the field), else by sorting.
  const auto nodes = static_cast<std::size_t>(lattice.nodeCount());
  if (nodes / 64 <= 4 * cells.size())
  {
    std::vector<std::uint64_t> bits(nodes / 64 + 1, 0);
    for (const std::int64_t c : cells)
    {
      bits[static_cast<std::size_t>(c) / 64] |= std::uint64_t(1) << (c % 64);
    }
    cells.clear();
    for (std::size_t w = 0; w < bits.size(); ++w)
    {
      for (std::uint64_t word = bits[w]; word != 0; word &= word - 1)
      {
        cells.push_back(
          static_cast<std::int64_t>(64 * w + static_cast<std::size_t>(__builtin_ctzll(word))));
      }
    }
  }
  else
  {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  return progress.report(1);
}

namespace
{
// The sparse spacing (PointSpacing): each sampled point's nearest-neighbour distance averaged over
// the sampled points within kLocalRadius of their own median spacing (a few dozen), and the 99th
// percentile of those local means over their median, which chance alone keeps below kUniformTail on
// uniform samples. Above it the excess, times kSparseGain (the percentile of a local mean lags the
// sparsest end), widens the median, so that a cloud whose density falls across it is not entered
// on its sparse side. A point with fewer than kLeastNeighbours sampled points within the radius
// (itself included) is a stray (a scan's outlier) and has no local mean.
constexpr double kLocalRadius = 8;
constexpr double kSparseQuantile = 0.99;
constexpr double kUniformTail = 1.35;
constexpr double kSparseGain = 1.5;
constexpr std::size_t kLocalMeans =
  5000; // at most, from evenly spread sampled points (5 ms, not 20)
constexpr int kLeastNeighbours = 5;

double quantile(std::vector<double> values, double q)
{
  const auto k = std::min(static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size())),
    static_cast<std::ptrdiff_t>(values.size()) - 1);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

double sparseFactor(
  const std::vector<Vec3>& sample, const std::vector<double>& nearest, double sampleSpacing)
{
  const double radius = kLocalRadius * sampleSpacing;
  const PointGrid grid(sample, radius);
  const std::size_t every = std::max<std::size_t>(1, sample.size() / kLocalMeans);
  std::vector<double> local((sample.size() + every - 1) / every);
  constexpr double kStray = -1;
  parallelFor(0, static_cast<Index>(local.size()), [&](Index b, Index e) {
    for (Index k = b; k < e; ++k)
    {
      double sum = 0;
      int count = 0;
      grid.forEachWithin(sample[k * every], radius, [&](int i, const Vec3&) {
        sum += nearest[i];
        ++count;
      });
      local[k] = count >= kLeastNeighbours ? sum / count : kStray; // the point itself is within
    }
  });
  local.erase(std::remove(local.begin(), local.end(), kStray), local.end());
  if (local.empty())
  {
    return 1;
  }
  const double typical = quantile(local, 0.5);
  const double tail = quantile(std::move(local), kSparseQuantile) / typical;
  return std::max(1.0, 1 + kSparseGain * (tail / kUniformTail - 1));
}
} // namespace

double medianNeighbourDistance(const std::vector<Vec3>& points)
{
  return points.size() < 2 ? 0.0 : PointSource(points).spacing().median;
}

PointSpacing PointSource::spacing() const
{
  const PointList& points = this->Points;
  const PointTree& tree = this->Tree;
  const std::size_t n = points.size();
  if (n < 2)
  {
    return {};
  }
  const std::size_t stride = std::max<std::size_t>(1, n / 20000);
  std::vector<double> nearest((n + stride - 1) / stride);
  parallelFor(0, static_cast<Index>(nearest.size()), [&](Index b, Index e) {
    for (Index k = b; k < e; ++k)
    {
      const Vec3& p = points[k * stride];
      nearest[k] =
        std::sqrt(tree.nearest(p, std::numeric_limits<double>::infinity(), true).squaredDistance);
    }
  });
  // Points with no neighbour apart (all at one position) count as infinitely far.
  const double median = quantile(nearest, 0.5);
  if (!(median < std::numeric_limits<double>::infinity()))
  {
    return {};
  }
  // The sampled points that have a neighbour apart, and the sample's own spacing (a surface's
  // sample of one point in `stride` lies sqrt(stride) times farther apart).
  std::vector<Vec3> sample;
  std::vector<double> apart;
  for (std::size_t k = 0; k < nearest.size(); ++k)
  {
    if (nearest[k] < std::numeric_limits<double>::infinity())
    {
      sample.push_back(points[k * stride]);
      apart.push_back(nearest[k]);
    }
  }
  return { median,
    median * sparseFactor(sample, apart, median * std::sqrt(static_cast<double>(stride))) };
}

SourcePoint PointSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  SourcePoint p;
  if (const PointTree::Hit hit = this->Tree.nearest(x, maxSquaredDistance); hit.id >= 0)
  {
    p.found = true;
    p.squaredDistance = hit.squaredDistance;
    p.point = this->Points[hit.id];
    p.element = hit.id;
  }
  p.sure = false; // a point has no sides
  return p;
}

} // namespace shrinkwrap
