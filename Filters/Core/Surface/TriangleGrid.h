// Triangle boxes binned in a uniform grid, for the neighbour queries of self-intersection tests.
// Cells are hashed into buckets stored end to end (counting sort, no comparison sort: the grid is
// rebuilt every evolution step). A bucket may hold triangles of several cells; queries filter by
// box overlap and report each triangle once, in the first cell (lowest i, j, k) its range shares
// with the query's.
#ifndef ShrinkWrap_TriangleGrid_h
#define ShrinkWrap_TriangleGrid_h

#include "Common/Box.h"
#include "Common/Vec3.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace shrinkwrap
{

class TriangleGrid
{
public:
  using Range = std::array<std::uint32_t, 6>; // first and last cell per axis

  // Cells two mean edges wide (no triangle in more than 9 x 9 x 9 cells).
  TriangleGrid(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);
  // Given boxes (e.g. swept over a step) in cells of the given size. `stop` (empty: never), asked
  // between the phases of the build, leaves the grid empty and stopped().
  TriangleGrid(std::vector<Box> boxes, double cell, const std::function<bool()>& stop = {});

  static double cellSizeFor(
    const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles);

  bool empty() const { return this->Items.empty(); }
  bool stopped() const { return this->Stopped; }
  double cell() const { return this->Cell; }
  const Box& box(int t) const { return this->Boxes[t]; }

  // f(t) once for every triangle whose box overlaps `box`.
  template <typename F>
  void forEachNear(const Box& box, F&& f) const;
  // f(s, t) once for every pair of triangles whose boxes overlap; buckets [begin, end) of
  // bucketCount(), so that threads can share the buckets.
  int bucketCount() const { return static_cast<int>(this->Start.size()) - 1; }
  template <typename F>
  void forEachOverlappingPair(int begin, int end, F&& f) const;

  // The cells a box covers (clamped to the grid's 2^21 cells an axis), and a cell's key.
  Range rangeOf(const Box& box) const;
  static std::uint64_t key(std::uint64_t i, std::uint64_t j, std::uint64_t k)
  {
    return (k << 42) | (j << 21) | i;
  }

private:
  void build(const std::function<bool()>& stop);
  std::uint32_t bucketOf(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    const std::uint64_t h = (i * 73856093ull) ^ (j * 19349663ull) ^ (k * 83492791ull);
    return static_cast<std::uint32_t>(h & this->Mask);
  }
  // Whether (i, j, k) is the first cell (lowest on every axis) that both ranges hold.
  static bool firstSharedIs(
    const Range& a, const Range& b, std::uint32_t i, std::uint32_t j, std::uint32_t k)
  {
    return std::max(a[0], b[0]) == i && std::max(a[1], b[1]) == j && std::max(a[2], b[2]) == k;
  }

  std::vector<Box> Boxes;
  std::vector<Range> Ranges;
  Range Extent{};                   // the cells the triangles cover
  std::vector<std::uint32_t> Start; // bucket b holds Items[Start[b], Start[b + 1])
  std::vector<int> Items;
  std::vector<Box> ItemBoxes; // Boxes[Items[p]], beside the items for the pair loops
  std::uint64_t Mask = 0;
  Vec3 Origin = Vec3::Zero();
  double Cell = 0;
  bool Stopped = false;
};

template <typename F>
void TriangleGrid::forEachNear(const Box& box, F&& f) const
{
  if (this->Items.empty() || box.empty())
  {
    return;
  }
  // Only the cells the triangles cover hold any; a box wider than the triangles have cells (a
  // search radius far beyond the surface's edge length) is answered by testing every triangle
  // instead.
  Range r = this->rangeOf(box);
  double cells = 1;
  for (int a = 0; a < 3; ++a)
  {
    r[a] = std::max(r[a], this->Extent[a]);
    r[a + 3] = std::min(r[a + 3], this->Extent[a + 3]);
    if (r[a] > r[a + 3])
    {
      return;
    }
    cells *= r[a + 3] - r[a] + 1.0;
  }
  if (cells > static_cast<double>(this->Boxes.size()))
  {
    for (int t = 0; t < static_cast<int>(this->Boxes.size()); ++t)
    {
      if (this->Boxes[t].overlaps(box))
      {
        f(t);
      }
    }
    return;
  }
  for (std::uint32_t k = r[2]; k <= r[5]; ++k)
    for (std::uint32_t j = r[1]; j <= r[4]; ++j)
      for (std::uint32_t i = r[0]; i <= r[3]; ++i)
      {
        const std::uint32_t b = this->bucketOf(i, j, k);
        for (std::uint32_t p = this->Start[b]; p < this->Start[b + 1]; ++p)
        {
          const int t = this->Items[p];
          if (this->Boxes[t].overlaps(box) && firstSharedIs(this->Ranges[t], r, i, j, k))
          {
            f(t);
          }
        }
      }
}

template <typename F>
void TriangleGrid::forEachOverlappingPair(int begin, int end, F&& f) const
{
  for (int b = begin; b < end; ++b)
  {
    for (std::uint32_t p = this->Start[b]; p < this->Start[b + 1]; ++p)
    {
      const int s = this->Items[p];
      const Box& bs = this->ItemBoxes[p];
      for (std::uint32_t q = p + 1; q < this->Start[b + 1]; ++q)
      {
        if (!bs.overlaps(this->ItemBoxes[q]))
        {
          continue;
        }
        const int t = this->Items[q];
        const Range& rs = this->Ranges[s];
        const Range& rt = this->Ranges[t];
        // Tested in the bucket of the first cell both hold, so once.
        if (this->bucketOf(std::max(rs[0], rt[0]), std::max(rs[1], rt[1]),
              std::max(rs[2], rt[2])) == static_cast<std::uint32_t>(b))
        {
          f(s, t);
        }
      }
    }
  }
}

} // namespace shrinkwrap

#endif
