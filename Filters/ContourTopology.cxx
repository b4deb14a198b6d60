#include "ContourTopology.h"

#include "Parallel.h"

#include <vtkMarchingCubesTriangleCases.h>

#include <array>
#include <atomic>

namespace shrinkwrap
{

namespace
{
// The cell's corners in the order of the case table's index bits (VTK's hexahedron).
constexpr int kCorner[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
  { 1, 1, 1 }, { 0, 1, 1 } };

std::array<int, 256> trianglesPerCase()
{
  std::array<int, 256> count{};
  const vtkMarchingCubesTriangleCases* cases = vtkMarchingCubesTriangleCases::GetCases();
  for (int c = 0; c < 256; ++c)
  {
    int edges = 0;
    while (edges < 16 && cases[c].edges[edges] >= 0)
    {
      ++edges;
    }
    count[c] = edges / 3;
  }
  return count;
}

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
} // namespace

ContourEuler contourEulerCharacteristic(const DistanceGrid& grid, double value)
{
  static const std::array<int, 256> triangles = trianglesPerCase(); // a constant table
  const GridLattice& lattice = grid.lattice();
  const std::vector<float>& v = grid.values();
  std::atomic<long long> twiceGrid{ 0 }, twiceFine{ 0 };
  parallelFor(0, lattice.dims[2] - 1, 1, [&](vtkIdType kb, vtkIdType ke) {
    long long sumGrid = 0, sumFine = 0;
    for (int k = static_cast<int>(kb); k < ke; ++k)
    {
      for (int j = 0; j + 1 < lattice.dims[1]; ++j)
      {
        for (int i = 0; i + 1 < lattice.dims[0]; ++i)
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
            continue; // no contour in the cell, nor in its finer cells
          }
          const auto at = [&](int a, int b, int c) { return corner[a][b][c]; };
          sumGrid += blockEuler(1, at, value, triangles);
          float fine[3][3][3]; // the interpolant at the cell's 3^3 half-spacing nodes
          for (int c = 0; c < 3; ++c)
            for (int b = 0; b < 3; ++b)
              for (int a = 0; a < 3; ++a)
              {
                fine[a][b][c] = DistanceGrid::halfSpacingValue(at, a, b, c);
              }
          sumFine += blockEuler(2, [&](int a, int b, int c) { return fine[a][b][c]; }, value, triangles);
        }
      }
    }
    twiceGrid += sumGrid;
    twiceFine += sumFine;
  });
  return { twiceGrid.load() / 2, twiceFine.load() / 2 };
}

} // namespace shrinkwrap
