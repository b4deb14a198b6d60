// Far field of Algorithm 1, line 7, by closest-point passes (the default): the band's exact closest
// surface points ("sites") spread to the grid in three passes, one per axis, as in separable exact
// distance transforms (Maurer et al. 2003, Felzenszwalb & Huttenlocher 2012): along each grid line,
// every node takes the site nearest to it among the sites the line's nodes hold, found exactly by
// the lower envelope of the parabolas (t - s_axis)^2 + (squared distance from the line to s). Each
// line is independent (parallel, linear time). A node's distance is then that to a true surface
// point, never below the exact one and far closer to it than the Eikonal scheme's first-order
// error.
#ifndef ShrinkWrap_ClosestPointSweep_h
#define ShrinkWrap_ClosestPointSweep_h

#include "Common/Progress.h"
#include "Distance/GridLattice.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shrinkwrap
{

// siteOfNode: index into sites for each node, -1 where none yet; on return every node has the
// nearest site found (if there is any site at all), and distance its distance to it.
bool sweepClosestPoints(const GridLattice& lattice, const SiteList& sites, std::int32_t* siteOfNode,
  float* distance, const Progress& progress);

// One slab of the planes of a lattice along z, computed by one of several processes
// (SlabDistance.h).
struct SlabPlanes
{
  GridLattice whole;
  int first = 0, last = -1;           // the planes this process computes (whole-grid indices)
  int ownedFirst = 0, ownedLast = -1; // the planes whose sites it gives (within first .. last); the
                                      // owned planes of all processes partition the whole grid's
};

// Sites per z column (x fastest): those of column c are sites[start[c]] .. sites[start[c + 1] - 1].
struct ColumnSites
{
  std::vector<std::int64_t> start;
  std::vector<std::int32_t> sites;
};

// The x and y passes over the slab's planes (`slab`: the lattice of those planes); they need
// nothing from other planes.
bool sweepClosestPointsInPlanes(const GridLattice& slab, const SiteList& sites,
  std::int32_t* siteOfNode, const Progress& progress);
// For each column, the sites of the owned planes that are the nearest of those to some node of the
// column in the wanted plane ranges (whole-grid [first, last], disjoint, ascending; the planes
// other processes compute): all that their z pass needs of this one.
ColumnSites columnWinners(const SlabPlanes& planes, const std::vector<std::array<int, 2>>& wanted,
  const SiteList& sites, std::int32_t* siteOfNode);
// The z pass of the slab: every node takes the site nearest to it among those of the owned planes
// in its column and `others` (the other processes' winners), with its distance. Equals the whole
// grid's z pass on these planes: the nearest site of a column, seen from a node, is the nearest of
// some process's planes, and that process's winners hold it.
void sweepColumns(const SlabPlanes& planes, const SiteList& sites, const ColumnSites& others,
  std::int32_t* siteOfNode, float* distance);

} // namespace shrinkwrap

#endif
