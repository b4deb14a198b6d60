#include "Distance/ContourTopology.h"

#include "Common/Parallel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

namespace shrinkwrap
{

namespace
{
// The cell's corners in the order of the case table's index bits (VTK's hexahedron).
constexpr int kCorner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
  { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };

// The cells of an n^3 block of nodes `at(a, b, c)` (a, b, c in [0, n]): their triangles, and the
// crossing edges each cell owns (the three from its lowest corner; the others belong to the cells
// beyond, which count them if they cross the value and cannot cross it otherwise).
template <typename At>
long long blockEuler(int n, const At& at, double value, const std::array<int, 256>& triangles)
{
  long long vertices = 0, faces = 0;
  for (int c = 0; c < n; ++c)
  {
    for (int b = 0; b < n; ++b)
    {
      for (int a = 0; a < n; ++a)
      {
        int index = 0;
        for (int k = 0; k < 8; ++k)
        {
          index |= (at(a + kCorner[k][0], b + kCorner[k][1], c + kCorner[k][2]) >= value) << k;
        }
        faces += triangles[index];
        const bool above = index & 1;
        vertices += (at(a + 1, b, c) >= value) != above;
        vertices += (at(a, b + 1, c) >= value) != above;
        vertices += (at(a, b, c + 1) >= value) != above;
      }
    }
  }
  return 2 * vertices - faces; // twice V - F / 2
}

// Twice the contributions of the cell with lowest corner (i, j, k) of values `v`: of the grid's
// contour and of the half spacing's.
ContourEuler cellEuler(
  const GridLattice& lattice, const FieldValues& v, int i, int j, int k, double value)
{
  float corner[2][2][2];
  bool below = false, above = false;
  for (int c = 0; c < 2; ++c)
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a)
      {
        corner[a][b][c] = v[lattice.index(i + a, j + b, k + c)];
        (corner[a][b][c] >= value ? above : below) = true;
      }
  if (!(above && below))
  {
    return {}; // no contour in the cell, nor in its finer cells
  }
  const auto at = [&](int a, int b, int c) { return corner[a][b][c]; };
  float fine[3][3][3]; // the interpolant at the cell's 3^3 half-spacing nodes
  for (int c = 0; c < 3; ++c)
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a)
      {
        fine[a][b][c] = DistanceGrid::halfSpacingValue(at, a, b, c);
      }
  return { blockEuler(1, at, value, marchingCubesTriangleCounts()),
    blockEuler(
      2, [&](int a, int b, int c) { return fine[a][b][c]; }, value,
      marchingCubesTriangleCounts()) };
}

// Twice the contributions of the cells around node n, the only ones its value enters.
ContourEuler aroundNode(
  const GridLattice& lattice, const FieldValues& v, std::int64_t n, double value)
{
  const std::array<int, 3> c = lattice.coordinates(n);
  ContourEuler sum;
  for (int z = std::max(c[2] - 1, 0); z <= std::min(c[2], lattice.dims[2] - 2); ++z)
    for (int y = std::max(c[1] - 1, 0); y <= std::min(c[1], lattice.dims[1] - 2); ++y)
      for (int x = std::max(c[0] - 1, 0); x <= std::min(c[0], lattice.dims[0] - 2); ++x)
      {
        const ContourEuler cell = cellEuler(lattice, v, x, y, z, value);
        sum.grid += cell.grid;
        sum.halfSpacing += cell.halfSpacing;
      }
  return sum;
}

// The shallower below corner of each face whose two diagonal corners lie below `value` while its
// bilinear saddle does not (sorted, each once).
std::vector<std::int64_t> wronglyJoinedCorners(const DistanceGrid& grid, double value)
{
  const GridLattice& lattice = grid.lattice();
  const FieldValues& v = grid.values();
  constexpr int kPlanes[3][2] = { { 0, 1 }, { 1, 2 }, { 0, 2 } };
  std::vector<std::int64_t> shallower;
  std::mutex lock;
  parallelFor(0, lattice.dims[2], 1, [&](Index kb, Index ke) {
    std::vector<std::int64_t> found;
    for (int k = static_cast<int>(kb); k < ke; ++k)
      for (int j = 0; j < lattice.dims[1]; ++j)
        for (int i = 0; i < lattice.dims[0]; ++i)
        {
          for (const auto& plane : kPlanes)
          {
            // The face's corners in turn: f00 at (i, j, k), f10, f11, f01 along the plane's axes.
            int a[3] = { i, j, k }, b[3] = { i, j, k }, c[3] = { i, j, k };
            ++a[plane[0]];
            ++b[plane[1]];
            ++c[plane[0]];
            ++c[plane[1]];
            if (c[plane[0]] >= lattice.dims[plane[0]] || c[plane[1]] >= lattice.dims[plane[1]])
            {
              continue;
            }
            const std::int64_t id[4] = { lattice.index(i, j, k), lattice.index(a[0], a[1], a[2]),
              lattice.index(c[0], c[1], c[2]), lattice.index(b[0], b[1], b[2]) };
            const double f00 = v[id[0]], f10 = v[id[1]], f11 = v[id[2]], f01 = v[id[3]];
            const bool below00 = f00 < value, below10 = f10 < value;
            if (below00 != (f11 < value) || below10 != (f01 < value) || below00 == below10)
            {
              continue; // not two diagonal pairs
            }
            // The bilinear interpolant's saddle value: at or above the value, the corners below are
            // apart.
            const double saddle = (f00 * f11 - f10 * f01) / (f00 + f11 - f10 - f01);
            if (saddle >= value)
            {
              found.push_back(below00 ? (f00 > f11 ? id[0] : id[2]) : (f10 > f01 ? id[1] : id[3]));
            }
          }
        }
    const std::lock_guard<std::mutex> guard(lock);
    shallower.insert(shallower.end(), found.begin(), found.end());
  });
  std::sort(shallower.begin(), shallower.end());
  shallower.erase(std::unique(shallower.begin(), shallower.end()), shallower.end());
  return shallower;
}
} // namespace

const std::array<int, 256>& marchingCubesTriangleCounts()
{
  static constexpr std::array<int, 256> kTriangles{ 0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 2,
    1, 2, 2, 3, 2, 3, 3, 4, 2, 3, 3, 4, 3, 4, 4, 3, 1, 2, 2, 3, 2, 3, 3, 4, 2, 3, 3, 4, 3, 4, 4, 3,
    2, 3, 3, 2, 3, 4, 4, 3, 3, 4, 4, 3, 4, 5, 5, 2, 1, 2, 2, 3, 2, 3, 3, 4, 2, 3, 3, 4, 3, 4, 4, 3,
    2, 3, 3, 4, 3, 4, 4, 5, 3, 4, 4, 5, 4, 5, 5, 4, 2, 3, 3, 4, 3, 4, 2, 3, 3, 4, 4, 5, 4, 5, 3, 2,
    3, 4, 4, 3, 4, 5, 3, 2, 4, 5, 5, 4, 5, 2, 4, 1, 1, 2, 2, 3, 2, 3, 3, 4, 2, 3, 3, 4, 3, 4, 4, 3,
    2, 3, 3, 4, 3, 4, 4, 5, 3, 2, 4, 3, 4, 3, 5, 2, 2, 3, 3, 4, 3, 4, 4, 5, 3, 4, 4, 5, 4, 5, 5, 4,
    3, 4, 4, 3, 4, 5, 5, 4, 4, 3, 5, 2, 5, 4, 2, 1, 2, 3, 3, 4, 3, 4, 4, 5, 3, 4, 4, 5, 2, 3, 3, 2,
    3, 4, 4, 5, 4, 5, 5, 2, 4, 3, 5, 4, 3, 2, 4, 1, 3, 4, 4, 5, 4, 5, 3, 4, 4, 5, 5, 2, 3, 4, 2, 1,
    2, 3, 3, 2, 3, 4, 2, 1, 3, 2, 4, 1, 2, 1, 1, 0 };
  return kTriangles;
}

std::vector<ContourEuler> contourEulerCharacteristics(
  const DistanceGrid& grid, const std::vector<double>& values)
{
  const GridLattice& lattice = grid.lattice();
  const FieldValues& v = grid.values();
  std::vector<ContourEuler> twice(values.size());
  std::mutex lock;
  parallelFor(0, lattice.dims[2] - 1, 1, [&](Index kb, Index ke) {
    std::vector<ContourEuler> sum(values.size());
    for (int k = static_cast<int>(kb); k < ke; ++k)
      for (int j = 0; j + 1 < lattice.dims[1]; ++j)
        for (int i = 0; i + 1 < lattice.dims[0]; ++i)
        {
          float low = std::numeric_limits<float>::infinity(), high = -low;
          for (const auto& corner : kCorner)
          {
            const float f = v[lattice.index(i + corner[0], j + corner[1], k + corner[2])];
            low = std::min(low, f);
            high = std::max(high, f);
          }
          for (std::size_t l = 0; l < values.size(); ++l)
          {
            if (low < values[l] && high >= values[l]) // the cell crosses this value (cellEuler)
            {
              const ContourEuler cell = cellEuler(lattice, v, i, j, k, values[l]);
              sum[l].grid += cell.grid;
              sum[l].halfSpacing += cell.halfSpacing;
            }
          }
        }
    const std::lock_guard<std::mutex> guard(lock);
    for (std::size_t l = 0; l < values.size(); ++l)
    {
      twice[l].grid += sum[l].grid;
      twice[l].halfSpacing += sum[l].halfSpacing;
    }
  });
  for (ContourEuler& e : twice)
  {
    e = { e.grid / 2, e.halfSpacing / 2 };
  }
  return twice;
}

ContourEuler contourEulerCharacteristic(const DistanceGrid& grid, double value)
{
  return contourEulerCharacteristics(grid, { value }).front();
}

DistanceGrid withFacesSeparated(const DistanceGrid& grid, double value)
{
  const GridLattice& lattice = grid.lattice();
  FieldValues values = grid.values();
  float at = static_cast<float>(value);
  while (at < value)
  {
    at = std::nextafter(at, std::numeric_limits<float>::infinity());
  }
  for (const std::int64_t n : wronglyJoinedCorners(grid, value))
  {
    // Raised where that leaves the interpolant's topology as it is (it had no such join) and does
    // not lower the grid's count: a join undone raises it, or keeps it where the join spans several
    // faces (each corner but the last leaves it). A corner whose raise would cut a handle of the
    // interpolant too (a true handle's) stays. Both counts change only in
    // the node's cells.
    const ContourEuler before = aroundNode(lattice, values, n, value);
    const float old = values[n];
    // Mirrored about the value rather than set to it: a corner at the value would put the contour's
    // vertices of all its edges on one point, slivers the start's coarsening labours over.
    values[n] = std::max(at, static_cast<float>(2 * value - old));
    const ContourEuler after = aroundNode(lattice, values, n, value);
    if (!(after.grid >= before.grid && after.halfSpacing == before.halfSpacing))
    {
      values[n] = old;
    }
  }
  return DistanceGrid(lattice, std::move(values));
}

TriangleSoup contourWithFewerJoins(const DistanceGrid& grid, double value, const Contour& contour)
{
  const ContourEuler euler = contourEulerCharacteristic(grid, value);
  return contour(euler.halfSpacing > euler.grid ? withFacesSeparated(grid, value) : grid, value);
}

} // namespace shrinkwrap
