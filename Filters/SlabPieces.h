// Mesh Signed Distance by pieces under MPI: whether the ranks can compute one field together, the
// slab of planes each computes, and the pieces of other shapes handed round from the slabs.
#ifndef ShrinkWrap_SlabPieces_h
#define ShrinkWrap_SlabPieces_h

#include "RankInputs.h"

#include "Common/TriangleSoup.h"
#include "Distance/GridLattice.h"

#include <array>
#include <string>

class vtkFloatArray;
class vtkImageData;
class vtkInformation;
class vtkMultiProcessController;

namespace shrinkwrap
{
namespace convert
{

struct Agreement
{
  std::string why;   // why they cannot: one of them could not read its input or place its grid, or
                     // they hold different surfaces or grids
  bool slabs = true; // every rank asks for whole planes (or nothing): each computes just those
};

// Whether the ranks, each with its input (`soup` and `loosePoints` points) and `lattice`, asking
// for the `update` extent, can compute one field together. Collective.
Agreement agree(const ControllerExchange& exchange, bool ready, const TriangleSoup& soup,
  std::size_t loosePoints, const GridLattice& lattice, const int update[6]);

using Extent = std::array<int, 6>;

// The planes rank r of n computes when the pieces asked for are not slabs: an even share.
Extent evenSlab(const GridLattice& lattice, int r, int n);

// Each rank's piece (`wanted`, its update extent, of any shape) from the ranks' slabs of planes
// (rank r holds evenSlab(r)): a gather to each rank of the parts of the others' slabs that its
// piece overlaps. Collective.
void piecesFromSlabs(vtkMultiProcessController* controller, const GridLattice& lattice,
  vtkFloatArray* slab, const int wanted[6], vtkFloatArray* piece);

// Ghost layers, when asked for (a contour or gradient across piece borders): the nodes of `output`
// beyond this piece proper (as the pipeline's extent translator splits the grid) are marked, so
// that their cells are not counted twice.
void markGhosts(const GridLattice& lattice, vtkInformation* outInfo, vtkImageData* output);

} // namespace convert
} // namespace shrinkwrap

#endif
