#include "FieldRun.h"

#include "RankInputs.h"
#include "SlabPieces.h"

#include "Common/HugePages.h"
#include "Common/Parallel.h"

#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationInformationVectorKey.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
// `count` values, in huge pages where the system gives them (their first writes fault in 2 MiB at a
// time); throws std::bad_alloc when the process may not have them.
void allocateValues(vtkFloatArray* values, std::int64_t count)
{
  void* buffer = allocateFreeable(static_cast<std::size_t>(count) * sizeof(float));
  if (!buffer)
  {
    throw std::bad_alloc();
  }
  values->SetArray(static_cast<float*>(buffer), count, 0, vtkFloatArray::VTK_DATA_ARRAY_FREE);
}

// The least and greatest of some values, of all and of the finite ones.
struct Extremes
{
  float low = std::numeric_limits<float>::infinity(), high = -low;
  float finiteLow = low, finiteHigh = high;
  void add(float v)
  {
    low = std::min(low, v);
    high = std::max(high, v);
    if (std::isfinite(v))
    {
      finiteLow = std::min(finiteLow, v);
      finiteHigh = std::max(finiteHigh, v);
    }
  }
  void add(const Extremes& e)
  {
    low = std::min(low, e.low);
    high = std::max(high, e.high);
    finiteLow = std::min(finiteLow, e.finiteLow);
    finiteHigh = std::max(finiteHigh, e.finiteHigh);
  }
};

// Stores [low, high] as the array's range of one kind (all values or the finite ones), where VTK
// keeps the range it computes: valid while the array is unmodified.
void keepRange(
  vtkDataArray* values, vtkInformationInformationVectorKey* kind, double low, double high)
{
  vtkNew<vtkInformationVector> components;
  components->SetNumberOfInformationObjects(1);
  const double range[2] = { low, high };
  components->GetInformationObject(0)->Set(vtkDataArray::COMPONENT_RANGE(), range, 2);
  values->GetInformation()->Set(kind, components);
}

// The field's ranges found on every core and kept by the array: ParaView's data information and
// colour map read them instead of scanning the grid again on one core.
void keepRanges(vtkFloatArray* values)
{
  const float* v = values->GetPointer(0);
  const vtkIdType count = values->GetNumberOfValues();
  if (count == 0)
  {
    return;
  }
  ThreadLocal<Extremes> partial;
  onAllCores([&] {
    parallelFor(0, count, 1 << 16, [&](Index b, Index e) {
      Extremes& local = partial.local();
      for (Index n = b; n < e; ++n)
      {
        local.add(v[n]);
      }
    });
  });
  Extremes all;
  partial.forEach([&](const Extremes& e) { all.add(e); });
  keepRange(values, vtkAbstractArray::PER_COMPONENT(), all.low, all.high);
  if (all.finiteLow <= all.finiteHigh)
  {
    keepRange(values, vtkAbstractArray::PER_FINITE_COMPONENT(), all.finiteLow, all.finiteHigh);
  }
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
    allocateValues(values, planesOf(lattice, first, last).nodeCount());
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
    if (result.completed)
    {
      keepRanges(values);
    }
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
