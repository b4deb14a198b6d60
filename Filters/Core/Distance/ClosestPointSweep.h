// Far field of Algorithm 1, line 7, by closest-point passes (the default): the band's exact closest
// surface points ("sites") spread to the grid in three passes, one per axis, as in separable exact
// distance transforms (Maurer et al. 2003, Felzenszwalb & Huttenlocher 2012): along each grid line,
// every node takes the site nearest to it among the sites the line's nodes hold, found exactly by the
// lower envelope of the parabolas (t - s_axis)^2 + (squared distance from the line to s). Each line is
// independent (parallel, linear time). A node's distance is then that to a true surface point, never
// below the exact one and far closer to it than the Eikonal scheme's first-order error.
#ifndef ShrinkWrap_ClosestPointSweep_h
#define ShrinkWrap_ClosestPointSweep_h

#include "GridLattice.h"
#include "Progress.h"

#include <cstdint>
#include <vector>

namespace shrinkwrap
{

// siteOfNode: index into sites for each node, -1 where none yet; on return every node has the
// nearest site found (if there is any site at all), and distance its distance to it.
bool sweepClosestPoints(const GridLattice& lattice, const std::vector<Vec3>& sites, std::int32_t* siteOfNode,
  float* distance, const Progress& progress);

} // namespace shrinkwrap

#endif
