// Mesh Signed Distance's computation as the filter runs it: the memory checked against what this
// process computes, the values in VTK's array, all cores, and under MPI this rank's share of the
// grid, computed with the other ranks.
#ifndef ShrinkWrap_FieldRun_h
#define ShrinkWrap_FieldRun_h

#include "Common/Progress.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/GridLattice.h"
#include "Distance/SignedDistance.h"
#include "Distance/SlabDistance.h"

class vtkFloatArray;
class vtkInformation;
class vtkMultiProcessController;

namespace shrinkwrap
{
namespace convert
{

// The input as the filter measures it.
struct MeasuredInput
{
  TriangleSoup soup;  // its triangles (none: points only)
  TriangleSoup cloud; // its points (none: polygons only), as the cloud's points
  GridLattice lattice;
};

// The distances at planes first .. last of the lattice into `values`: all of them, or with
// `exchange` this MPI rank's piece, computed with the other ranks. A failure says why (memory, a
// rank that cannot); an abort leaves `result.completed` false.
Status computeField(const MeasuredInput& measured, int first, int last,
  const SlabExchange* exchange, const SignedDistanceSettings& settings, const Progress& progress,
  vtkFloatArray* values, SignedDistanceResult& result);

// This rank's piece (the update extent of `outInfo`, into `extent`) computed with the other ranks.
// Collective: every rank must measure the same surface on the same grid (`ready`: this one could),
// and one that cannot, or holds another input, stops all of them rather than leave the others
// waiting for it.
Status computePieces(vtkMultiProcessController* controller, bool ready,
  const MeasuredInput& measured, const SignedDistanceSettings& settings, const Progress& progress,
  vtkInformation* outInfo, int extent[6], vtkFloatArray* values, SignedDistanceResult& result);

} // namespace convert
} // namespace shrinkwrap

#endif
