#include "Surface/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

double TriangleGrid::cellSizeFor(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  Box all;
  double edges = 0, longest = 0;
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      all.extend(x[t[k]]);
      const double length = (x[t[k]] - x[t[(k + 1) % 3]]).norm();
      edges += length;
      longest = std::max(longest, length);
    }
  }
  const double nt = static_cast<double>(triangles.size());
  const double cell =
    nt > 0 ? std::max({ 2 * edges / (3.0 * nt), longest / 8, 1e-9 * all.diagonal() }) : 0;
  return std::isfinite(cell) && std::isfinite(all.diagonal()) ? cell : 0;
}

namespace
{
std::vector<Box> boxesOf(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  std::vector<Box> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    boxes[t] = Box::around(x, triangles[t]);
  }
  return boxes;
}
} // namespace

TriangleGrid::TriangleGrid(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
  : TriangleGrid(boxesOf(x, triangles), cellSizeFor(x, triangles))
{
}

TriangleGrid::TriangleGrid(std::vector<Box> boxes, double cell, const std::function<bool()>& stop)
  : Boxes(std::move(boxes))
  , Cell(cell)
{
  Box all;
  double largest = 0;
  for (const Box& b : this->Boxes)
  {
    all.extend(b);
    largest = std::max(largest, b.size().maxCoeff());
  }
  if (this->Boxes.empty() || !(cell > 0) || !std::isfinite(cell) || !all.min.allFinite() ||
    !all.max.allFinite())
  {
    return;
  }
  // No box in more than 9 x 9 x 9 cells, whatever the cell asked for: a swept box of a vertex that
  // jumped far (a fuzzed step) would otherwise cover billions.
  this->Cell = std::max(cell, largest / 8);
  this->Origin = all.min;
  this->Extent = this->rangeOf(all);
  this->build(stop);
  if (this->Stopped)
  {
    *this = TriangleGrid({}, 0);
    this->Stopped = true;
  }
}

// Counting sort of (cell, triangle) into buckets; a triangle whose cells share a bucket is stored
// once. `stop` is asked between the passes.
void TriangleGrid::build(const std::function<bool()>& stop)
{
  const auto stopped = [&] { return this->Stopped = this->Stopped || (stop && stop()); };
  const int nt = static_cast<int>(this->Boxes.size());
  this->Ranges.resize(nt);
  std::size_t entries = 0;
  for (int t = 0; t < nt; ++t)
  {
    const Range& r = this->Ranges[t] = this->rangeOf(this->Boxes[t]);
    entries += std::size_t(r[3] - r[0] + 1) * (r[4] - r[1] + 1) * (r[5] - r[2] + 1);
  }
  if (stopped())
  {
    return;
  }
  std::uint64_t buckets = 1;
  while (buckets < entries)
  {
    buckets <<= 1;
  }
  this->Mask = buckets - 1;
  std::vector<int> last(buckets, -1); // the last triangle counted in each bucket
  this->Start.assign(buckets + 1, 0);
  auto forEachBucket = [&](int t, auto&& f) {
    const Range& r = this->Ranges[t];
    for (std::uint32_t k = r[2]; k <= r[5]; ++k)
      for (std::uint32_t j = r[1]; j <= r[4]; ++j)
        for (std::uint32_t i = r[0]; i <= r[3]; ++i)
        {
          const std::uint32_t b = this->bucketOf(i, j, k);
          if (last[b] != t)
          {
            last[b] = t;
            f(b);
          }
        }
  };
  for (int t = 0; t < nt; ++t)
  {
    forEachBucket(t, [&](std::uint32_t b) { ++this->Start[b + 1]; });
  }
  if (stopped())
  {
    return;
  }
  for (std::uint64_t b = 0; b < buckets; ++b)
  {
    this->Start[b + 1] += this->Start[b];
  }
  this->Items.resize(this->Start[buckets]);
  std::vector<std::uint32_t> fill(this->Start.begin(), this->Start.end() - 1);
  std::fill(last.begin(), last.end(), -1);
  for (int t = 0; t < nt; ++t)
  {
    forEachBucket(t, [&](std::uint32_t b) { this->Items[fill[b]++] = t; });
  }
  if (stopped())
  {
    return;
  }
  this->ItemBoxes.resize(this->Items.size());
  for (std::size_t p = 0; p < this->Items.size(); ++p)
  {
    this->ItemBoxes[p] = this->Boxes[this->Items[p]];
  }
}

TriangleGrid::Range TriangleGrid::rangeOf(const Box& box) const
{
  Range r{};
  for (int a = 0; a < 3; ++a)
  {
    // Clamped to 2^21 cells an axis (a query box may reach beyond the surface's).
    const auto cellOf = [&](double v) {
      return static_cast<std::uint32_t>(
        std::clamp((v - this->Origin[a]) / this->Cell, 0.0, 2097151.0));
    };
    r[a] = cellOf(box.min[a]);
    r[a + 3] = cellOf(box.max[a]);
  }
  return r;
}

} // namespace shrinkwrap
