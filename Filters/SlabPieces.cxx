#include "SlabPieces.h"

#include <vtkExtentTranslator.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationIntegerRequestKey.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cstring>
#include <sstream>

namespace shrinkwrap
{
namespace convert
{

namespace
{
Extent intersection(const Extent& a, const Extent& b)
{
  return { std::max(a[0], b[0]), std::min(a[1], b[1]), std::max(a[2], b[2]), std::min(a[3], b[3]),
    std::max(a[4], b[4]), std::min(a[5], b[5]) };
}

vtkIdType nodesOf(const Extent& e)
{
  return e[1] < e[0] || e[3] < e[2] || e[5] < e[4]
    ? 0
    : static_cast<vtkIdType>(e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1);
}

// Calls f(index in `within`, index in `part`) for each x run of `part` (a sub-extent of `within`):
// its first node's indices, row by row.
template <typename F>
void forEachRow(const Extent& within, const Extent& part, F&& f)
{
  const vtkIdType wx = within[1] - within[0] + 1, wy = within[3] - within[2] + 1;
  vtkIdType at = 0;
  for (int k = part[4]; k <= part[5]; ++k)
  {
    for (int j = part[2]; j <= part[3]; ++j, at += part[1] - part[0] + 1)
    {
      f((part[0] - within[0]) + wx * ((j - within[2]) + wy * (k - within[4])), at);
    }
  }
}

} // namespace

Agreement agree(const ControllerExchange& exchange, bool ready, const TriangleSoup& soup,
  std::size_t loosePoints, const GridLattice& lattice, const int update[6])
{
  struct Fingerprint
  {
    char ready;
    std::int64_t points, triangles, loose;
    int dims[3];
    double origin[3], spacing[3];
    int update[6];
  } mine{ ready, static_cast<std::int64_t>(soup.points.size()),
    static_cast<std::int64_t>(soup.triangles.size()), static_cast<std::int64_t>(loosePoints),
    { lattice.dims[0], lattice.dims[1], lattice.dims[2] },
    { lattice.origin[0], lattice.origin[1], lattice.origin[2] },
    { lattice.spacing[0], lattice.spacing[1], lattice.spacing[2] },
    { update[0], update[1], update[2], update[3], update[4], update[5] } };
  const char* bytes = reinterpret_cast<const char*>(&mine);
  const Messages all = exchange.allGather(std::vector<char>(bytes, bytes + sizeof(mine)));
  std::ostringstream why;
  Agreement agreement;
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    Fingerprint other;
    std::memcpy(&other, all.data(r), sizeof(other));
    const int* e = other.update;
    agreement.slabs = agreement.slabs &&
      (e[5] < e[4] ||
        (e[0] == 0 && e[1] == other.dims[0] - 1 && e[2] == 0 && e[3] == other.dims[1] - 1));
    if (!why.str().empty())
    {
      continue;
    }
    if (!other.ready)
    {
      why << "MPI rank " << r << " cannot (see its error).";
    }
    else if (ready &&
      (other.points != mine.points || other.triangles != mine.triangles ||
        other.loose != mine.loose || !std::equal(other.dims, other.dims + 3, mine.dims) ||
        !std::equal(other.origin, other.origin + 3, mine.origin) ||
        !std::equal(other.spacing, other.spacing + 3, mine.spacing)))
    {
      why << "MPI rank " << r << " holds " << other.triangles << " triangles and a "
          << other.dims[0] << " x " << other.dims[1] << " x " << other.dims[2] << " grid, rank "
          << exchange.rank() << " " << mine.triangles << " and " << mine.dims[0] << " x "
          << mine.dims[1] << " x " << mine.dims[2]
          << " (every rank needs the whole input and the same grid settings).";
    }
  }
  agreement.why = why.str();
  return agreement;
}

// The planes rank r of n computes when the pieces asked for are not slabs: an even share.
Extent evenSlab(const GridLattice& lattice, int r, int n)
{
  return { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, r * lattice.dims[2] / n,
    (r + 1) * lattice.dims[2] / n - 1 };
}

// Each rank's piece (`wanted`, its update extent, of any shape) from the ranks' slabs of planes
// (rank r holds evenSlab(r)): a gather to each rank
// of the parts of the others' slabs that its piece overlaps. Collective.
void piecesFromSlabs(vtkMultiProcessController* controller, const GridLattice& lattice,
  vtkFloatArray* slab, const int wanted[6], vtkFloatArray* piece)
{
  const int n = controller->GetNumberOfProcesses(), rank = controller->GetLocalProcessId();
  std::vector<int> all(6 * n);
  controller->AllGather(wanted, all.data(), 6);
  auto slabOf = [&](int r) { return evenSlab(lattice, r, n); };
  const Extent mine = slabOf(rank);
  const Extent own = { wanted[0], wanted[1], wanted[2], wanted[3], wanted[4], wanted[5] };
  piece->SetName(slab->GetName());
  piece->SetNumberOfValues(nodesOf(own));
  for (int d = 0; d < n; ++d)
  {
    const Extent target = { all[6 * d], all[6 * d + 1], all[6 * d + 2], all[6 * d + 3],
      all[6 * d + 4], all[6 * d + 5] };
    const Extent part = intersection(mine, target);
    const int width = part[1] - part[0] + 1;
    std::vector<float> send(nodesOf(part));
    if (!send.empty())
    {
      forEachRow(mine, part, [&](vtkIdType from, vtkIdType to) {
        std::copy_n(slab->GetPointer(from), width, send.data() + to);
      });
    }
    std::vector<vtkIdType> lengths(n, 0), offsets(n, 0);
    for (int r = 0; r < n; ++r)
    {
      lengths[r] = nodesOf(intersection(slabOf(r), target));
      offsets[r] = r > 0 ? offsets[r - 1] + lengths[r - 1] : 0;
    }
    std::vector<float> received(rank == d ? offsets[n - 1] + lengths[n - 1] : 0);
    controller->GatherV(send.data(), received.data(), static_cast<vtkIdType>(send.size()),
      lengths.data(), offsets.data(), d);
    for (int r = 0; rank == d && r < n; ++r)
    {
      const Extent from = intersection(slabOf(r), target);
      const int w = from[1] - from[0] + 1;
      if (nodesOf(from) > 0)
      {
        forEachRow(own, from, [&](vtkIdType to, vtkIdType at) {
          std::copy_n(received.data() + offsets[r] + at, w, piece->GetPointer(to));
        });
      }
    }
  }
}

// Ghost layers, when asked for (a contour or gradient across piece borders): the nodes beyond the
// piece proper (as the pipeline's extent translator splits the grid) are marked, so that their
// cells are not counted twice.
void markGhosts(
  const shrinkwrap::GridLattice& lattice, vtkInformation* outInfo, vtkImageData* output)
{
  int whole[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
  int proper[6];
  vtkNew<vtkExtentTranslator> translator;
  vtkInformationIntegerRequestKey* split = vtkExtentTranslator::UPDATE_SPLIT_MODE();
  translator->PieceToExtentThreadSafe(
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()),
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()), 0, whole, proper,
    split->Has(outInfo) ? split->Get(outInfo) : vtkExtentTranslator::BLOCK_MODE, 0);
  output->GenerateGhostArray(proper);
}

} // namespace convert
} // namespace shrinkwrap
