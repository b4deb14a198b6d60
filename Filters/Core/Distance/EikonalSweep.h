// Far field of Algorithm 1, line 7, by the paper's fast sweeping (Zhao 2005 [16]): Godunov upwind
// updates of |grad d| = 1 in the 2^3 = 8 sweep orderings.
#ifndef ShrinkWrap_EikonalSweep_h
#define ShrinkWrap_EikonalSweep_h

#include "Common/Progress.h"
#include "Distance/GridLattice.h"

#include <cstdint>

namespace shrinkwrap
{

// distance: the band values where frozen[n] is nonzero (band nodes), anything elsewhere; unsigned
// distances out.
bool sweepEikonal(const GridLattice& lattice, const std::uint8_t* frozen, float* distance,
  int iterations, const Progress& progress);

} // namespace shrinkwrap

#endif
