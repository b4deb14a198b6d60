#include "Distance/ClosestPointSweep.h"
#include "Common/Parallel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace shrinkwrap
{

namespace
{
// One grid line for the closest-point passes: the nodes' site indices, with a stride.
struct Line
{
  std::int32_t* site;
  std::int64_t stride;
  int length;
  double origin; // coordinate of node 0 of the whole grid line along the line's axis
  double step;
  int first =
    0; // index of the line's first node on the whole grid line (a slab's column starts later)
};

// Scratch space of one thread for the lower envelope of one line.
struct Envelope
{
  struct Parabola
  {
    // The site's coordinate along the line, from the line's origin: the envelope's cuts subtract
    // squares of it, which far from the origin (1e9) would lose every digit a cell has.
    double vertex;
    double offset; // squared distance from the line to the site
    std::int32_t site;
  };
  std::vector<Parabola> candidates;
  std::vector<int> hull;        // candidates on the lower envelope, left to right
  std::vector<double> boundary; // where hull[k] starts to win

  // The sites the line's nodes hold (those of nodes first .. end - 1 only), each run once.
  template <typename OffsetOf>
  void collect(const Line& line, int axis, const SiteList& sites, OffsetOf&& offsetOf,
    int first = 0, int end = -1)
  {
    this->candidates.clear();
    for (int t = first; t < (end < 0 ? line.length : end); ++t)
    {
      const std::int32_t s = line.site[t * line.stride];
      if (s >= 0 && (this->candidates.empty() || this->candidates.back().site != s))
      {
        this->add(line, axis, sites, offsetOf, s);
      }
    }
  }
  template <typename OffsetOf>
  void add(const Line& line, int axis, const SiteList& sites, OffsetOf&& offsetOf, std::int32_t s)
  {
    this->candidates.push_back({ sites[s][axis] - line.origin, offsetOf(sites[s]), s });
  }

  // The lower envelope of the candidates (Felzenszwalb & Huttenlocher 2012, with sites off the
  // line: parabolas (t - vertex)^2 + offset).
  void build()
  {
    // Sites lie within a few cells of their nodes, so the list is nearly sorted: insertion sort.
    auto& c = this->candidates;
    for (std::size_t a = 1; a < c.size(); ++a)
    {
      for (std::size_t b = a; b > 0 && c[b].vertex < c[b - 1].vertex; --b)
      {
        std::swap(c[b], c[b - 1]);
      }
    }
    this->hull.assign(1, 0);
    this->boundary.assign(1, -std::numeric_limits<double>::infinity());
    for (int q = 1; q < static_cast<int>(c.size()); ++q)
    {
      double cut = 0;
      while (!this->hull.empty())
      {
        const auto& p = c[this->hull.back()];
        if (c[q].vertex == p.vertex)
        {
          // Same vertex: the lower parabola wins everywhere.
          if (c[q].offset >= p.offset)
          {
            break;
          }
          this->hull.pop_back();
          this->boundary.pop_back();
          continue;
        }
        cut = ((c[q].offset + c[q].vertex * c[q].vertex) - (p.offset + p.vertex * p.vertex)) /
          (2 * (c[q].vertex - p.vertex));
        if (cut > this->boundary.back())
        {
          break;
        }
        this->hull.pop_back();
        this->boundary.pop_back();
      }
      if (this->hull.empty())
      {
        this->hull.push_back(q);
        this->boundary.push_back(-std::numeric_limits<double>::infinity());
      }
      else if (c[q].vertex != c[this->hull.back()].vertex)
      {
        this->hull.push_back(q);
        this->boundary.push_back(cut);
      }
    }
  }

  // The hull entry that wins at whole-line node t (as the sweep of `assign` finds it).
  std::size_t winnerAt(const Line& line, int t) const
  {
    const double x = t * line.step;
    const auto after = std::lower_bound(this->boundary.begin() + 1, this->boundary.end(), x);
    return static_cast<std::size_t>(after - this->boundary.begin()) - 1;
  }

  // Every node of the line takes the site nearest to it among the candidates; with `distance` (the
  // last pass), each node's distance to its site is written there too.
  void assign(const Line& line, float* distance)
  {
    if (this->candidates.empty())
    {
      for (int t = 0; distance && t < line.length; ++t)
      {
        distance[t * line.stride] =
          std::numeric_limits<float>::infinity(); // no surface on the grid
      }
      return;
    }
    std::size_t k = 0;
    for (int t = 0; t < line.length; ++t)
    {
      const double x = (line.first + t) * line.step;
      while (k + 1 < this->hull.size() && this->boundary[k + 1] < x)
      {
        ++k;
      }
      const Parabola& best = this->candidates[this->hull[k]];
      line.site[t * line.stride] = best.site;
      if (distance)
      {
        distance[t * line.stride] =
          static_cast<float>(std::sqrt((x - best.vertex) * (x - best.vertex) + best.offset));
      }
    }
  }

  template <typename OffsetOf>
  void apply(
    const Line& line, int axis, const SiteList& sites, OffsetOf&& offsetOf, float* distance)
  {
    this->collect(line, axis, sites, offsetOf);
    if (!this->candidates.empty())
    {
      this->build();
    }
    this->assign(line, distance);
  }
};

// The pass along `axis`: every line parallel to it, in parallel. Lines are taken in index order
// (x fastest among the others), so neighbouring lines reuse the same cache lines. False when
// `progress` asked to stop (reported over batches of lines).
bool envelopePass(const GridLattice& lattice, const SiteList& sites, std::int32_t* site, int axis,
  float* distance, const Progress& progress)
{
  const auto& d = lattice.dims;
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2; // the two other axes, u varying fastest
  const std::int64_t strides[3] = { 1, d[0], static_cast<std::int64_t>(d[0]) * d[1] };
  ThreadLocal<Envelope> scratch;
  return forChunks(static_cast<long long>(d[w]), 4, progress, [&](long long b, long long e) {
    Envelope& envelope = scratch.local();
    for (long long lw = b; lw < e; ++lw)
    {
      const double cw = lattice.origin[w] + lw * lattice.spacing[w];
      for (int lu = 0; lu < d[u]; ++lu)
      {
        const double cu = lattice.origin[u] + lu * lattice.spacing[u];
        const std::int64_t first = lu * strides[u] + lw * strides[w];
        const Line line{ site + first, strides[axis], d[axis], lattice.origin[axis],
          lattice.spacing[axis] };
        envelope.apply(
          line, axis, sites,
          [&](const Vec3& s) { return (s[u] - cu) * (s[u] - cu) + (s[w] - cw) * (s[w] - cw); },
          distance ? distance + first : nullptr);
      }
    }
  });
}
} // namespace

bool sweepClosestPoints(const GridLattice& lattice, const SiteList& sites, std::int32_t* siteOfNode,
  float* distance, const Progress& progress)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!envelopePass(lattice, sites, siteOfNode, axis, axis == 2 ? distance : nullptr,
          progress.stage(axis / 3.0, (axis + 1) / 3.0)))
    {
      return false;
    }
  }
  return true;
}

bool sweepClosestPointsInPlanes(const GridLattice& slab, const SiteList& sites,
  std::int32_t* siteOfNode, const Progress& progress)
{
  for (int axis = 0; axis < 2; ++axis)
  {
    if (!envelopePass(
          slab, sites, siteOfNode, axis, nullptr, progress.stage(axis / 2.0, (axis + 1) / 2.0)))
    {
      return false;
    }
  }
  return true;
}

namespace
{
// Calls f(envelope, column line, i, j) for every z column of the slab, rows of columns in parallel
// (f of one row in order of i).
template <typename F>
void forEachColumn(const SlabPlanes& planes, std::int32_t* siteOfNode, F&& f)
{
  const GridLattice& whole = planes.whole;
  const int nx = whole.dims[0], ny = whole.dims[1];
  const std::int64_t plane = static_cast<std::int64_t>(nx) * ny;
  ThreadLocal<Envelope> scratch;
  parallelFor(0, ny, [&](Index b, Index e) {
    Envelope& envelope = scratch.local();
    for (Index j = b; j < e; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const Line line{ siteOfNode + i + j * nx, plane, planes.last - planes.first + 1,
          whole.origin[2], whole.spacing[2], planes.first };
        f(envelope, line, i, static_cast<int>(j));
      }
    }
  });
}

auto columnOffset(const GridLattice& whole, int i, int j)
{
  const double cu = whole.origin[0] + i * whole.spacing[0],
               cw = whole.origin[1] + j * whole.spacing[1];
  return [cu, cw](const Vec3& s) { return (s[0] - cu) * (s[0] - cu) + (s[1] - cw) * (s[1] - cw); };
}
} // namespace

ColumnSites columnWinners(const SlabPlanes& planes, const std::vector<std::array<int, 2>>& wanted,
  const SiteList& sites, std::int32_t* siteOfNode)
{
  const GridLattice& whole = planes.whole;
  const int nx = whole.dims[0], ny = whole.dims[1], nz = whole.dims[2];
  const int ownedBegin = planes.ownedFirst - planes.first,
            ownedEnd = planes.ownedLast - planes.first + 1;
  std::vector<std::vector<std::int32_t>> rowCounts(ny), rowSites(ny);
  forEachColumn(planes, siteOfNode, [&](Envelope& envelope, const Line& line, int i, int j) {
    auto& counts = rowCounts[j];
    auto& out = rowSites[j];
    if (i == 0)
    {
      counts.assign(nx, 0);
    }
    envelope.collect(line, 2, sites, columnOffset(whole, i, j), ownedBegin, ownedEnd);
    if (envelope.candidates.empty())
    {
      return;
    }
    envelope.build();
    const std::size_t before = out.size();
    // The hull entries winning at the nodes of each wanted range: a run of the hull each.
    auto addRun = [&](int t0, int t1) {
      if (t0 > t1)
      {
        return;
      }
      for (std::size_t k = envelope.winnerAt(line, t0); k <= envelope.winnerAt(line, t1); ++k)
      {
        const std::int32_t s = envelope.candidates[envelope.hull[k]].site;
        if (out.size() == before || out.back() != s)
        {
          out.push_back(s);
        }
      }
    };
    for (const auto& range : wanted)
    {
      addRun(std::max(range[0], 0), std::min(range[1], nz - 1));
    }
    counts[i] = static_cast<std::int32_t>(out.size() - before);
  });
  ColumnSites result;
  result.start.reserve(static_cast<std::size_t>(nx) * ny + 1);
  result.start.push_back(0);
  for (int j = 0; j < ny; ++j)
  {
    for (std::int32_t c : rowCounts[j])
    {
      result.start.push_back(result.start.back() + c);
    }
    result.sites.insert(result.sites.end(), rowSites[j].begin(), rowSites[j].end());
  }
  return result;
}

void sweepColumns(const SlabPlanes& planes, const SiteList& sites, const ColumnSites& others,
  std::int32_t* siteOfNode, float* distance)
{
  const GridLattice& whole = planes.whole;
  const int nx = whole.dims[0];
  const int ownedBegin = planes.ownedFirst - planes.first,
            ownedEnd = planes.ownedLast - planes.first + 1;
  forEachColumn(planes, siteOfNode, [&](Envelope& envelope, const Line& line, int i, int j) {
    const auto offsetOf = columnOffset(whole, i, j);
    envelope.collect(line, 2, sites, offsetOf, ownedBegin, ownedEnd);
    const std::size_t column = i + static_cast<std::size_t>(j) * nx;
    for (std::int64_t k = others.start[column]; k < others.start[column + 1]; ++k)
    {
      envelope.add(line, 2, sites, offsetOf, others.sites[k]);
    }
    if (!envelope.candidates.empty())
    {
      envelope.build();
    }
    envelope.assign(line, distance + (line.site - siteOfNode));
  });
}

} // namespace shrinkwrap
