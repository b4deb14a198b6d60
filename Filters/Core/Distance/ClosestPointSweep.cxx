#include "ClosestPointSweep.h"
#include "Parallel.h"

#include <vtkSMPThreadLocal.h>
#include <vtkSMPTools.h>

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
  double origin; // coordinate of the first node along the line's axis
  double step;
};

// Scratch space of one thread for the lower envelope of one line.
struct Envelope
{
  struct Parabola
  {
    // The site's coordinate along the line, from the line's first node: the envelope's cuts subtract
    // squares of it, which far from the origin (1e9) would lose every digit a cell has.
    double vertex;
    double offset; // squared distance from the line to the site
    std::int32_t site;
  };
  std::vector<Parabola> candidates;
  std::vector<int> hull;        // candidates on the lower envelope, left to right
  std::vector<double> boundary; // where hull[k] starts to win

  // Every node of the line takes the site nearest to it among the sites its nodes hold
  // (Felzenszwalb & Huttenlocher 2012, with sites off the line: parabolas (t - vertex)^2 + offset).
  // With `distance` (the last pass), each node's distance to its site is written there too.
  template <typename OffsetOf>
  void apply(const Line& line, int axis, const std::vector<Vec3>& sites, OffsetOf&& offsetOf, float* distance)
  {
    this->candidates.clear();
    for (int t = 0; t < line.length; ++t)
    {
      const std::int32_t s = line.site[t * line.stride];
      if (s >= 0 && (this->candidates.empty() || this->candidates.back().site != s))
      {
        this->candidates.push_back({ sites[s][axis] - line.origin, offsetOf(sites[s]), s });
      }
    }
    if (this->candidates.empty())
    {
      for (int t = 0; distance && t < line.length; ++t)
      {
        distance[t * line.stride] = std::numeric_limits<float>::infinity(); // no surface on the grid
      }
      return;
    }
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
    std::size_t k = 0;
    for (int t = 0; t < line.length; ++t)
    {
      const double x = t * line.step;
      while (k + 1 < this->hull.size() && this->boundary[k + 1] < x)
      {
        ++k;
      }
      const Parabola& best = c[this->hull[k]];
      line.site[t * line.stride] = best.site;
      if (distance)
      {
        distance[t * line.stride] =
          static_cast<float>(std::sqrt((x - best.vertex) * (x - best.vertex) + best.offset));
      }
    }
  }
};

// The pass along `axis`: every line parallel to it, in parallel. Lines are taken in index order
// (x fastest among the others), so neighbouring lines reuse the same cache lines.
void envelopePass(
  const GridLattice& lattice, const std::vector<Vec3>& sites, std::int32_t* site, int axis, float* distance)
{
  const auto& d = lattice.dims;
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2; // the two other axes, u varying fastest
  const std::int64_t strides[3] = { 1, d[0], static_cast<std::int64_t>(d[0]) * d[1] };
  vtkSMPThreadLocal<Envelope> scratch;
  parallelFor(0, static_cast<long long>(d[w]), [&](long long b, long long e) {
    Envelope& envelope = scratch.Local();
    for (long long lw = b; lw < e; ++lw)
    {
      const double cw = lattice.origin[w] + lw * lattice.spacing[w];
      for (int lu = 0; lu < d[u]; ++lu)
      {
        const double cu = lattice.origin[u] + lu * lattice.spacing[u];
        const std::int64_t first = lu * strides[u] + lw * strides[w];
        const Line line{ site + first, strides[axis], d[axis], lattice.origin[axis], lattice.spacing[axis] };
        envelope.apply(
          line, axis, sites,
          [&](const Vec3& s) { return (s[u] - cu) * (s[u] - cu) + (s[w] - cw) * (s[w] - cw); },
          distance ? distance + first : nullptr);
      }
    }
  });
}
} // namespace

bool sweepClosestPoints(const GridLattice& lattice, const std::vector<Vec3>& sites, std::int32_t* siteOfNode,
  float* distance, const Progress& progress)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    envelopePass(lattice, sites, siteOfNode, axis, axis == 2 ? distance : nullptr);
    if (!progress.report((axis + 1) / 3.0))
    {
      return false;
    }
  }
  return true;
}

} // namespace shrinkwrap
