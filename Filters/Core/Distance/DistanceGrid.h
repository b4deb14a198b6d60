// A signed distance field on a node lattice (the lattice Mesh Signed Distance writes), sampled
// trilinearly. The gradient is that of the same trilinear interpolant, so d and grad d agree.
// Points outside the grid are clamped to its boundary.
#ifndef ShrinkWrap_DistanceGrid_h
#define ShrinkWrap_DistanceGrid_h

#include "GridLattice.h"

#include <vector>

namespace shrinkwrap
{

struct DistanceSample
{
  double value;
  Vec3 gradient;
};

class DistanceGrid
{
public:
  DistanceGrid() = default;
  DistanceGrid(const GridLattice& lattice, std::vector<float> values)
    : Lattice(lattice)
    , Values(std::move(values))
  {
  }

  const GridLattice& lattice() const { return this->Lattice; }
  bool empty() const { return this->Values.empty(); }
  const std::vector<float>& values() const { return this->Values; }
  DistanceSample sample(const Vec3& x) const;

  // The same trilinear interpolant sampled at half the spacing (the nodes kept): a contour of it
  // follows the interpolant's topology more closely where marching cubes on this grid resolves an
  // ambiguous face the other way.
  DistanceGrid refined() const;

private:
  GridLattice Lattice;
  std::vector<float> Values;
};

} // namespace shrinkwrap

#endif
