#include "FieldRun.h"

#include "RankInputs.h"
#include "SlabPieces.h"

#include "Common/Parallel.h"

#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

namespace shrinkwrap
{
namespace convert
{

namespace
{
// Why the planes cannot be computed in this process's memory, if they cannot: under MPI what must
// fit is this rank's piece with a few planes around it, not the grid; and every rank's must fit
// (collective).
Status checkPlanes(const GridLattice& lattice, int first, int last, const SlabExchange* exchange,
  const SignedDistanceSettings& settings)
{
  const int halo = exchange ? settings.bandLayers + 2 : 0;
  const GridLattice planes =
    planesOf(lattice, std::max(0, first - halo), std::min(lattice.dims[2] - 1, last + halo));
  Status fits = checkMemory(planes, settings);
  if (!fits)
  {
    fits = Status::failure("Cannot compute the field: " + fits.message() +
      "; lower Resolution or raise Cell Size" + (exchange ? ", or run on more MPI ranks" : ""));
  }
  if (exchange && !everyProcess(*exchange, fits.ok()) && fits)
  {
    fits = Status::failure("Cannot compute the field: another MPI rank cannot (see its error)");
  }
  return fits;
}
} // namespace

Status computeField(const MeasuredInput& measured, int first, int last,
  const SlabExchange* exchange, const SignedDistanceSettings& settings, const Progress& progress,
  vtkFloatArray* values, SignedDistanceResult& result)
{
  const GridLattice& lattice = measured.lattice;
  if (const Status fits = checkPlanes(lattice, first, last, exchange, settings); !fits)
  {
    return fits;
  }
  values->SetName("SignedDistance");
  try // the memory estimate can be beaten by a process limit (ulimit -v, a job's cap)
  {
    if (!values->SetNumberOfValues(planesOf(lattice, first, last).nodeCount()))
    {
      throw std::bad_alloc();
    }
    onAllCores([&] {
      float* distance = values->GetPointer(0);
      if (!exchange)
      {
        result = computeDistance(
          measured.soup, measured.cloud.points, lattice, settings, distance, progress);
        return;
      }
      const Status status = computeSlabDistance(measured.soup, measured.cloud.points, lattice,
        first, last, settings, *exchange, distance, result, progress);
      if (!status)
      {
        throw std::runtime_error(status.message());
      }
    });
  }
  catch (const std::bad_alloc&)
  {
    return Status::failure("Out of memory for a " + std::to_string(lattice.dims[0]) + " x " +
      std::to_string(lattice.dims[1]) + " x " + std::to_string(lattice.dims[2]) +
      " grid: the process may not allocate it; lower Resolution or raise Cell Size");
  }
  catch (const std::exception& e) // e.g. threads that cannot start under the same limits
  {
    return Status::failure(std::string("Mesh Signed Distance failed: ") + e.what());
  }
  return {};
}

Status computePieces(vtkMultiProcessController* controller, bool ready,
  const MeasuredInput& measured, const SignedDistanceSettings& settings, const Progress& progress,
  vtkInformation* outInfo, int extent[6], vtkFloatArray* values, SignedDistanceResult& result)
{
  const ControllerExchange exchange(controller);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const Agreement agreement =
    agree(exchange, ready, measured.soup, measured.cloud.points.size(), measured.lattice, extent);
  if (!agreement.why.empty())
  {
    return Status::failure("Cannot compute the field by pieces: " + agreement.why);
  }
  if (agreement.slabs) // slabs of whole planes (the split this filter asks for): each its own
  {
    return computeField(
      measured, extent[4], extent[5], &exchange, settings, progress, values, result);
  }
  // Pieces of other shapes (a consumer that splits otherwise): even shares of planes, handed round.
  const Extent share =
    evenSlab(measured.lattice, controller->GetLocalProcessId(), controller->GetNumberOfProcesses());
  vtkNew<vtkFloatArray> slab;
  const Status status =
    computeField(measured, share[4], share[5], &exchange, settings, progress, slab, result);
  if (status && result.completed)
  {
    piecesFromSlabs(controller, measured.lattice, slab, extent, values);
  }
  return status;
}

} // namespace convert
} // namespace shrinkwrap
