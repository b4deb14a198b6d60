// The voxel outline of Algorithm 2: the grid cells the surface touches, found by an octree that
// subdivides only the cells the surface touches, down to single grid cells.
#ifndef ShrinkWrap_Outline_h
#define ShrinkWrap_Outline_h

#include "Common/Progress.h"
#include "Common/TriangleSoup.h"
#include "Distance/GridLattice.h"

#include <cstdint>
#include <vector>

namespace shrinkwrap
{

// Algorithm 2: grid cells intersected by the soup, found by an octree whose nodes pass the
// triangles touching them on to their children. Returns false if aborted.
bool outlineCells(
  const TriangleSoup& soup, const GridLattice& lattice, const Progress& progress, IndexList& cells);

} // namespace shrinkwrap

#endif
