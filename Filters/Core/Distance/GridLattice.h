// The node lattice of a distance grid: index <-> position. Values live at the nodes (VTK point
// data), so the shrink-wrap evolver samples exactly the lattice the signed distance filter writes.
#ifndef ShrinkWrap_GridLattice_h
#define ShrinkWrap_GridLattice_h

#include "Common/Box.h"
#include "Common/HugePages.h"
#include "Common/Status.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace shrinkwrap
{

// Grid node or cell indices, and points per node or site (the closest points that the
// closest-point passes spread): a fine grid's band, outline and sites are megabytes, in huge pages.
using IndexList = LargeVector<std::int64_t>;
using SiteList = LargeVector<Vec3>;
using NodeFlags = LargeVector<char>; // a yes or no per node

struct GridLattice
{
  Vec3 origin = Vec3::Zero();
  Vec3 spacing = Vec3::Ones();
  std::array<int, 3> dims = { 0, 0, 0 }; // nodes per axis

  std::int64_t nodeCount() const
  {
    return static_cast<std::int64_t>(this->dims[0]) * this->dims[1] * this->dims[2];
  }
  std::int64_t index(int i, int j, int k) const
  {
    return i +
      static_cast<std::int64_t>(this->dims[0]) * (j + static_cast<std::int64_t>(this->dims[1]) * k);
  }
  // (i, j, k) of node index n.
  std::array<int, 3> coordinates(std::int64_t n) const
  {
    const std::int64_t row = n / this->dims[0];
    return { static_cast<int>(n - row * this->dims[0]), static_cast<int>(row % this->dims[1]),
      static_cast<int>(row / this->dims[1]) };
  }
  Vec3 position(const std::array<int, 3>& c) const { return this->position(c[0], c[1], c[2]); }
  Vec3 position(int i, int j, int k) const
  {
    return this->origin + Vec3(i, j, k).cwiseProduct(this->spacing);
  }
  Box bounds() const
  {
    Box b;
    b.extend(this->origin);
    b.extend(this->position(this->dims[0] - 1, this->dims[1] - 1, this->dims[2] - 1));
    return b;
  }
  double minSpacing() const { return this->spacing.minCoeff(); }
  bool operator==(const GridLattice& other) const
  {
    return this->origin == other.origin && this->spacing == other.spacing &&
      this->dims == other.dims;
  }
  bool operator!=(const GridLattice& other) const { return !(*this == other); }
};

// Planes first .. last (along z) of a lattice, as a lattice of their own.
inline GridLattice planesOf(const GridLattice& whole, int first, int last)
{
  GridLattice planes = whole;
  planes.origin[2] += first * whole.spacing[2];
  planes.dims[2] = std::max(0, last - first + 1);
  return planes;
}

// Calls f(node index) once for every node on the faces of the box of node indices
// box = (imin, imax, jmin, jmax, kmin, kmax), inclusive.
template <typename F>
void forEachFaceNode(const GridLattice& lattice, const std::array<int, 6>& box, F&& f)
{
  for (int k = box[4]; k <= box[5]; ++k)
  {
    for (int j = box[2]; j <= box[3]; ++j)
    {
      const bool face = k == box[4] || k == box[5] || j == box[2] || j == box[3];
      const int step = face ? 1 : std::max(1, box[1] - box[0]); // inside rows: both ends only
      for (int i = box[0]; i <= box[1]; i += step)
      {
        f(lattice.index(i, j, k));
      }
    }
  }
}

// The paper's offset o (Section 4.1: o = the largest side of the scaled box): room for a start
// anywhere around the target, such as its icosphere.
constexpr double kPaperOffsetFactor = 1.0;

// How the grid is placed around a mesh (paper Section 4.1 and Algorithm 1, lines 3-4). The default
// offset is 0.15, not the paper's 1.0: the cells go to the object (84 across it at Resolution 120
// rather than 36), and the margin still holds an offset start of a few cells with its gap closing,
// which a wrap reusing the field needs (measured on the trefoil: largest distance 0.009 against
// 0.2).
struct GridPlacement
{
  double boxScale = 1.1; // phi: the mesh bounds are scaled by it about their centre
  double offsetFactor =
    0.15; // o = offsetFactor * the largest side of the scaled box, added on every side
  int resolution = 120; // cells along the longest axis of the whole grid ("120^3" in Table 1)
  double cellSize = 0;  // > 0 overrides resolution
};

// Coordinates beyond +-1e30 are refused: distances are stored as float (largest 3.4e38) and their
// squares are formed in double (largest 1.8e308).
constexpr double kLargestCoordinate = 1e30;
bool withinCoordinateRange(const Box& box);

// The lattice for a mesh with the given bounds; equal spacing on all axes. Fails with a
// message for bounds that are empty or not finite, or settings that make no grid.
Status placeGrid(const Box& meshBounds, const GridPlacement& placement, GridLattice& lattice);

// A lattice spanning explicit bounds with the given node counts (as Resample To Image does).
Status explicitGrid(const Box& bounds, const std::array<int, 3>& dims, GridLattice& lattice);

} // namespace shrinkwrap

#endif
