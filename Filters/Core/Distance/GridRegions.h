// Which free nodes of a grid the border reaches through free face neighbours (6-connectivity): what
// a flood fill from the border finds, and what it leaves are cavities. The closing of a point set
// fills those (GapClosing.h). Found by joining runs of free nodes along x, row by row, in memory
// order (a flood fill's queue would jump across the grid).
#ifndef ShrinkWrap_GridRegions_h
#define ShrinkWrap_GridRegions_h

#include "Distance/GridLattice.h"

#include <vector>

namespace shrinkwrap
{

// Per node of `lattice`: 1 where it is free (blocked[n] == 0) and a path of free face neighbours
// joins it to a node on the grid's border.
NodeFlags reachedFromBorder(const GridLattice& lattice, const NodeFlags& blocked);

} // namespace shrinkwrap

#endif
