// A signed distance field on a node lattice (the lattice Mesh Signed Distance writes), sampled
// trilinearly. The gradient is that of the same trilinear interpolant, so d and grad d agree.
// Points outside the grid are clamped to its boundary.
#ifndef ShrinkWrap_DistanceGrid_h
#define ShrinkWrap_DistanceGrid_h

#include "Common/HugePages.h"
#include "Distance/GridLattice.h"

#include <vector>

namespace shrinkwrap
{

struct DistanceSample
{
  double value;
  Vec3 gradient;
};

// A field's node values, x fastest (in huge pages where the system gives them: a fine field's
// first writes would otherwise fault in a small page at a time).
using FieldValues = LargeVector<float>;

class DistanceGrid
{
public:
  DistanceGrid() = default;
  DistanceGrid(const GridLattice& lattice, FieldValues values)
    : Lattice(lattice)
    , Values(std::move(values))
  {
  }
  // A copy of plain values (the tests' grids; the filters' fields are FieldValues from the start).
  DistanceGrid(const GridLattice& lattice, const std::vector<float>& values)
    : DistanceGrid(lattice, FieldValues(values.begin(), values.end()))
  {
  }

  const GridLattice& lattice() const { return this->Lattice; }
  bool empty() const { return this->Values.empty(); }
  const FieldValues& values() const { return this->Values; }
  DistanceSample sample(const Vec3& x) const;

  // The same trilinear interpolant sampled at half the spacing (the nodes kept): a contour of it
  // follows the interpolant's topology more closely where marching cubes on this grid resolves an
  // ambiguous face the other way. ContourTopology counts that contour's Euler characteristic cell
  // by cell without building the grid; the grid itself is for checking the count.
  DistanceGrid refined() const;

  // The interpolant at half-spacing node (i, j, k) of the values `at(i, j, k)` on this spacing: the
  // mean of the 8 corners (i / 2 or (i + 1) / 2, ...), repeated where the node lies on an old edge,
  // face or node. Summed in double and rounded once, so it lies between the corners' floats (a node
  // on an old node keeps its value exactly): a cell whose corners are all on one side of a level
  // has no finer crossing, which ContourTopology relies on. One formula for refined() and
  // ContourTopology, so a value near the level falls on the same side in both.
  template <typename At>
  static float halfSpacingValue(const At& at, int i, int j, int k)
  {
    const int i0 = i / 2, i1 = (i + 1) / 2, j0 = j / 2, j1 = (j + 1) / 2, k0 = k / 2,
              k1 = (k + 1) / 2;
    const double sum = double(at(i0, j0, k0)) + at(i1, j0, k0) + at(i0, j1, k0) + at(i1, j1, k0) +
      at(i0, j0, k1) + at(i1, j0, k1) + at(i0, j1, k1) + at(i1, j1, k1);
    return static_cast<float>(0.125 * sum);
  }

private:
  GridLattice Lattice;
  FieldValues Values;
};

} // namespace shrinkwrap

#endif
