#include "vtkMeshSignedDistance.h"

#include "Common/Parallel.h"
#include "Distance/SignedDistance.h"
#include "Distance/SlabDistance.h"
#include "VTKConversions.h"
#include "RankInputs.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkExtentTranslator.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cstring>
#include <array>
#include <vector>
#include <new>
#include <stdexcept>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkMeshSignedDistance);

namespace convert = shrinkwrap::convert;

namespace
{
// Whether the ranks can compute one field together, and how. Collective.
struct Agreement
{
  std::string why; // why they cannot: one of them could not read its input or place its grid, or
                   // they hold different surfaces or grids
  bool slabs = true; // every rank asks for whole planes (or nothing): each computes just those
};

Agreement agree(const convert::ControllerExchange& exchange, bool ready, const shrinkwrap::TriangleSoup& soup,
  const shrinkwrap::TriangleSoup& cloud, const shrinkwrap::GridLattice& lattice, const int update[6])
{
  struct Fingerprint
  {
    char ready;
    std::int64_t points, triangles, loose;
    int dims[3];
    double origin[3], spacing[3];
    int update[6];
  } mine{ ready, static_cast<std::int64_t>(soup.points.size()), static_cast<std::int64_t>(soup.triangles.size()),
    static_cast<std::int64_t>(cloud.points.size()), { lattice.dims[0], lattice.dims[1], lattice.dims[2] },
    { lattice.origin[0], lattice.origin[1], lattice.origin[2] },
    { lattice.spacing[0], lattice.spacing[1], lattice.spacing[2] },
    { update[0], update[1], update[2], update[3], update[4], update[5] } };
  const char* bytes = reinterpret_cast<const char*>(&mine);
  const shrinkwrap::Messages all = exchange.allGather(std::vector<char>(bytes, bytes + sizeof(mine)));
  std::ostringstream why;
  Agreement agreement;
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    Fingerprint other;
    std::memcpy(&other, all.data(r), sizeof(other));
    const int* e = other.update;
    agreement.slabs = agreement.slabs &&
      (e[5] < e[4] || (e[0] == 0 && e[1] == other.dims[0] - 1 && e[2] == 0 && e[3] == other.dims[1] - 1));
    if (!why.str().empty())
    {
      continue;
    }
    if (!other.ready)
    {
      why << "MPI rank " << r << " cannot (see its error).";
    }
    else if (ready &&
      (other.points != mine.points || other.triangles != mine.triangles || other.loose != mine.loose ||
        !std::equal(other.dims, other.dims + 3, mine.dims) || !std::equal(other.origin, other.origin + 3, mine.origin) ||
        !std::equal(other.spacing, other.spacing + 3, mine.spacing)))
    {
      why << "MPI rank " << r << " holds " << other.triangles << " triangles and a " << other.dims[0] << " x "
          << other.dims[1] << " x " << other.dims[2] << " grid, rank " << exchange.rank() << " " << mine.triangles
          << " and " << mine.dims[0] << " x " << mine.dims[1] << " x " << mine.dims[2]
          << " (every rank needs the whole input and the same grid settings).";
    }
  }
  agreement.why = why.str();
  return agreement;
}

using Extent = std::array<int, 6>;

// The planes rank r of n computes when the pieces asked for are not slabs: an even share.
Extent evenSlab(const shrinkwrap::GridLattice& lattice, int r, int n)
{
  return { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, r * lattice.dims[2] / n, (r + 1) * lattice.dims[2] / n - 1 };
}

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

// Each rank's piece (`wanted`, its update extent, of any shape) from the ranks' slabs of planes
// (rank r holds evenSlab(r)): a gather to each rank
// of the parts of the others' slabs that its piece overlaps. Collective.
void piecesFromSlabs(vtkMultiProcessController* controller, const shrinkwrap::GridLattice& lattice,
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
    const Extent target = { all[6 * d], all[6 * d + 1], all[6 * d + 2], all[6 * d + 3], all[6 * d + 4], all[6 * d + 5] };
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
    controller->GatherV(send.data(), received.data(), static_cast<vtkIdType>(send.size()), lengths.data(),
      offsets.data(), d);
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
} // namespace

vtkMeshSignedDistance::vtkMeshSignedDistance()
{
  const shrinkwrap::GridPlacement placement;
  this->BoxScale = placement.boxScale;
  this->OffsetFactor = placement.offsetFactor;
  this->Resolution = placement.resolution;
  this->CellSize = placement.cellSize;
  const shrinkwrap::SignedDistanceSettings distance;
  this->SweepMethod = distance.sweep == shrinkwrap::SweepMethod::Eikonal ? EIKONAL : CLOSEST_POINT;
  this->BandLayers = distance.bandLayers;
  this->ComputeSign = distance.computeSign;
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
  this->SetProgressText("Mesh Signed Distance");
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkMeshSignedDistance::~vtkMeshSignedDistance()
{
  this->SetController(nullptr);
}

vtkCxxSetObjectMacro(vtkMeshSignedDistance, Controller, vtkMultiProcessController);

int vtkMeshSignedDistance::FillInputPortInformation(int, vtkInformation* info)
{
  // Composite inputs are taken whole (one field of all their meshes): left to the composite pipeline,
  // they would run once per block.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkMeshSignedDistance::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject"); // an image, or a composite of them
  return 1;
}

vtkTypeBool vtkMeshSignedDistance::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

// FieldPerBlock with a composite input gives a composite of the same kind (a field per block),
// anything else an image.
int vtkMeshSignedDistance::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  convert::makeOutput<vtkImageData>(outputVector->GetInformationObject(0),
    this->FieldPerBlock ? vtkCompositeDataSet::GetData(inputVector[0], 0) : nullptr);
  return 1;
}

shrinkwrap::Status vtkMeshSignedDistance::ComputeLattice(
  const shrinkwrap::Box& surfaceBounds, shrinkwrap::GridLattice& lattice) const
{
  if (this->UseExplicitGrid)
  {
    shrinkwrap::Box box; // as given: inverted bounds are an error, not swapped
    box.min = shrinkwrap::Vec3(this->OutputBounds[0], this->OutputBounds[2], this->OutputBounds[4]);
    box.max = shrinkwrap::Vec3(this->OutputBounds[1], this->OutputBounds[3], this->OutputBounds[5]);
    return shrinkwrap::explicitGrid(
      box, { this->OutputDimensions[0], this->OutputDimensions[1], this->OutputDimensions[2] }, lattice);
  }
  const shrinkwrap::GridPlacement placement{ this->BoxScale, this->OffsetFactor, this->Resolution, this->CellSize };
  return shrinkwrap::placeGrid(surfaceBounds, placement, lattice);
}

int vtkMeshSignedDistance::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Downstream filters (slices, contours, streaming) need the grid now. A grid placed around the
  // input needs the input's bounds, so the input is brought up to date here; RequestData derives the
  // same lattice from the same bounds.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  this->GridCellSize = 0;
  if (vtkCompositeDataSet::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    return 1; // a field per block: a grid of its own for each
  }
  shrinkwrap::Box bounds;
  if (!this->UseExplicitGrid && this->GetNumberOfInputConnections(0) > 0)
  {
    vtkAlgorithm* producer = this->GetInputAlgorithm(0, 0);
    const int port = this->GetInputConnection(0, 0)->GetIndex();
    producer->UpdatePiece(0, 1, 0);
    vtkDataObject* input = convert::wholeInput(producer->GetOutputDataObject(port), this->Controller, this->Gathered);
    // The bounds of what ReadInput will measure.
    const shrinkwrap::Box polygons = convert::surfaceBounds(convert::polygonMeshes(input).meshes);
    const convert::Geometry use = convert::chooseGeometry(this->InputGeometry, !polygons.empty());
    if (use.polygons)
    {
      bounds.extend(polygons);
    }
    if (use.points)
    {
      bounds.extend(convert::pointBounds(input));
    }
  }
  shrinkwrap::GridLattice lattice;
  if (this->ComputeLattice(bounds, lattice))
  {
    this->GridCellSize = lattice.spacing.maxCoeff();
    const int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    outInfo->Set(vtkDataObject::ORIGIN(), lattice.origin.data(), 3);
    outInfo->Set(vtkDataObject::SPACING(), lattice.spacing.data(), 3);
    outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
    vtkExtentTranslator::UPDATE_SPLIT_MODE()->Set(outInfo, vtkExtentTranslator::Z_SLAB_MODE);
  }
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

int vtkMeshSignedDistance::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Distances need the whole mesh.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

int vtkMeshSignedDistance::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    this->ExecuteBlocks(vtkCompositeDataSet::GetData(inputVector[0], 0), outInfo, blocks);
    return 1;
  }
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  // Under MPI with a piece per rank, this rank computes an even share of the grid's planes with
  // the others (SlabDistance.h), and the ranks then hand each other what their pieces hold; otherwise
  // the whole grid (a request for part of it is cropped).
  vtkMultiProcessController* controller = this->Controller;
  vtkDataObject* input = convert::wholeInput(vtkDataObject::GetData(inputVector[0], 0), this->Controller, this->Gathered);
  const bool byPieces = controller && controller->GetNumberOfProcesses() > 1 &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) == controller->GetNumberOfProcesses() &&
    this->SweepMethod == CLOSEST_POINT && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT());
  shrinkwrap::TriangleSoup soup, cloud;
  shrinkwrap::Box bounds;
  shrinkwrap::GridLattice lattice;
  bool ready = this->ReadInput(input, soup, cloud, bounds);
  if (const shrinkwrap::Status placed = ready ? this->ComputeLattice(bounds, lattice) : shrinkwrap::Status(); !placed)
  {
    vtkErrorMacro("Cannot place the grid: " << placed.message() << ".");
    ready = false;
  }
  // Every rank must measure the same surface on the same grid: a rank that cannot, or holds another
  // input, stops all of them (rather than leave the others waiting for it).
  int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
  const convert::ControllerExchange exchange(controller);
  Agreement agreement;
  if (byPieces)
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    agreement = agree(exchange, ready, soup, cloud, lattice, extent);
    if (!agreement.why.empty())
    {
      vtkErrorMacro("Cannot compute the field by pieces: " << agreement.why);
      return 1;
    }
  }
  if (!ready)
  {
    return 1;
  }
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  if (byPieces && agreement.slabs)
  {
    // The pieces are slabs of whole planes (the split this filter asks for): each rank computes its own.
    if (!this->Compute(soup, cloud, lattice, extent[4], extent[5], &exchange, values, result))
    {
      return 1;
    }
  }
  else if (byPieces)
  {
    // Pieces of other shapes (a consumer that splits otherwise): even shares of planes, then handed round.
    const Extent share = evenSlab(lattice, controller->GetLocalProcessId(), controller->GetNumberOfProcesses());
    vtkNew<vtkFloatArray> slab;
    if (!this->Compute(soup, cloud, lattice, share[4], share[5], &exchange, slab, result))
    {
      return 1;
    }
    piecesFromSlabs(controller, lattice, slab, extent, values);
  }
  else if (!this->Compute(soup, cloud, lattice, 0, lattice.dims[2] - 1, nullptr, values, result))
  {
    return 1;
  }
  output->SetExtent(extent);
  output->SetOrigin(lattice.origin.data());
  output->SetSpacing(lattice.spacing.data());
  output->GetPointData()->SetScalars(values);
  // A downstream request for part of the grid (streaming) gets that part.
  if (!byPieces && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    output->Crop(extent);
  }
  // Ghost layers, when asked for (a contour or gradient across piece borders): the nodes beyond the
  // piece proper (as the pipeline's extent translator splits the grid) are marked, so that their
  // cells are not counted twice.
  if (byPieces && outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) > 0)
  {
    int whole[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 }, proper[6];
    vtkNew<vtkExtentTranslator> translator;
    vtkInformationIntegerRequestKey* split = vtkExtentTranslator::UPDATE_SPLIT_MODE();
    translator->PieceToExtentThreadSafe(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()),
      outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()), 0, whole, proper,
      split->Has(outInfo) ? split->Get(outInfo) : vtkExtentTranslator::BLOCK_MODE, 0);
    output->GenerateGhostArray(proper);
  }
  this->AddStatus(result, output);
  return 1;
}

bool vtkMeshSignedDistance::FieldOf(vtkDataObject* input, vtkImageData* output)
{
  shrinkwrap::TriangleSoup soup, cloud;
  shrinkwrap::Box bounds;
  shrinkwrap::GridLattice lattice;
  if (!this->ReadInput(input, soup, cloud, bounds))
  {
    return true;
  }
  if (const shrinkwrap::Status placed = this->ComputeLattice(bounds, lattice); !placed)
  {
    vtkErrorMacro("Cannot place the grid: " << placed.message() << ".");
    return true;
  }
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  if (!this->Compute(soup, cloud, lattice, 0, lattice.dims[2] - 1, nullptr, values, result))
  {
    return false;
  }
  output->SetDimensions(lattice.dims.data());
  output->SetOrigin(lattice.origin.data());
  output->SetSpacing(lattice.spacing.data());
  output->GetPointData()->SetScalars(values);
  this->AddStatus(result, output);
  return true;
}

// Each block's field is computed whole in one process; under MPI the blocks are shared out among the
// pieces by their grids' nodes, or computed where they are when the composite arrives distributed
// (the other pieces leave a block empty).
void vtkMeshSignedDistance::ExecuteBlocks(vtkCompositeDataSet* input, vtkInformation* outInfo, vtkCompositeDataSet* output)
{
  output->Initialize();
  output->CopyStructure(input);
  const convert::PieceRequest request = convert::pieceRequest(outInfo);
  vtkSmartPointer<vtkCompositeDataIterator> block = vtkSmartPointer<vtkCompositeDataIterator>::Take(input->NewIterator());
  std::vector<vtkDataSet*> leaves;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    leaves.push_back(vtkDataSet::SafeDownCast(block->GetCurrentDataObject()));
  }
  const std::vector<int> computedOn = convert::piecesOfLeaves(input, leaves, request, this->Controller, [&] {
    std::vector<double> nodes; // the cost of a block's field
    for (vtkDataSet* leaf : leaves)
    {
      shrinkwrap::GridLattice lattice;
      const bool placed = leaf && this->ComputeLattice(convert::boundsOf(leaf), lattice);
      nodes.push_back(placed ? static_cast<double>(lattice.dims[0]) * lattice.dims[1] * lattice.dims[2] : 1.0);
    }
    return convert::shareOut(nodes, request.pieces);
  });
  const int piece = request.piece;
  const auto here = static_cast<double>(std::count(computedOn.begin(), computedOn.end(), piece));
  std::size_t count = 0;
  int done = 0;
  bool goOn = true; // until a run is aborted or runs out of memory
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem(), ++count)
  {
    vtkNew<vtkImageData> field;
    if (goOn && leaves[count] && computedOn[count] == piece)
    {
      this->SetProgressShiftScale(done++ / here, 1 / here); // one progress bar over the blocks
      goOn = this->FieldOf(leaves[count], field);
    }
    output->SetDataSet(block, field);
  }
  this->SetProgressShiftScale(0, 1);
}

bool vtkMeshSignedDistance::ReadInput(vtkDataObject* data, shrinkwrap::TriangleSoup& soup,
  shrinkwrap::TriangleSoup& cloud, shrinkwrap::Box& bounds)
{
  const convert::PolygonMeshes input = convert::polygonMeshes(data);
  const std::vector<vtkPolyData*>& meshes = input.meshes;
  convert::SoupCounts counts;
  soup = convert::soupOf(meshes, counts);
  const convert::Geometry use =
    convert::chooseGeometry(this->InputGeometry, !soup.triangles.empty() || counts.badCells > 0);
  bounds = shrinkwrap::Box();
  if (use.polygons)
  {
    if (soup.triangles.empty() && counts.badCells == 0)
    {
      vtkErrorMacro("Cannot measure distances: the input has no polygons or 3-D cells, and Input Geometry is "
                    "Polygons; choose Automatic or Points to measure its points.");
      return false;
    }
    if (!input.extractedFrom.empty())
    {
      vtkOutputWindowDisplayText(("Mesh Signed Distance: the input (" + input.extractedFrom +
        ") is measured by its outer surface, as Extract Surface gives it.\n").c_str());
    }
    if (!use.points && (counts.lines > 0 || counts.vertices > 0))
    {
      vtkWarningMacro("Ignoring " << counts.lines << " lines and " << counts.vertices
                                  << " vertices: only polygons and triangle strips have an inside.");
    }
    if (counts.badCells > 0)
    {
      vtkErrorMacro("The input has " << counts.badCells << " cells whose point ids are out of range: it is corrupt.");
      return false;
    }
    if (const shrinkwrap::Status status = shrinkwrap::checkSoup(soup); !status)
    {
      vtkErrorMacro("Cannot measure distances: " << status.message() << ".");
      return false;
    }
    bounds = convert::surfaceBounds(meshes);
  }
  else
  {
    soup = shrinkwrap::TriangleSoup();
  }
  cloud = shrinkwrap::TriangleSoup();
  if (use.points)
  {
    // A point cloud, or the points beside the polygons (issue #13): the polygons' own corners lie on
    // them already.
    if (use.polygons)
    {
      for (vtkPolyData* mesh : meshes)
      {
        const std::vector<shrinkwrap::Vec3> loose = convert::loosePointsOf<std::vector<shrinkwrap::Vec3>>(mesh);
        cloud.points.insert(cloud.points.end(), loose.begin(), loose.end());
      }
      if (cloud.points.empty())
      {
        vtkWarningMacro("Input Geometry is Polygons and Points, but every point of the input lies on its polygons: "
                        "the polygons are measured.");
        return true;
      }
    }
    else
    {
      cloud.points = convert::pointsOf<std::vector<shrinkwrap::Vec3>>(data);
    }
    if (const shrinkwrap::Status status = shrinkwrap::checkPoints(cloud.points); !status)
    {
      vtkErrorMacro("Cannot measure distances: " << status.message() << ".");
      return false;
    }
    vtkOutputWindowDisplayText(("Mesh Signed Distance: the field is the unsigned distance to the nearest of " +
      std::string(use.polygons ? "the input's polygons and " : "its ") + std::to_string(cloud.points.size()) +
      (use.polygons ? " points beside them" : " points") + (this->InputGeometry == AUTOMATIC ? " (it has no polygons)" : "") + ".\n").c_str());
    bounds.extend(shrinkwrap::Box::around(cloud.points));
  }
  return true;
}

shrinkwrap::SignedDistanceSettings vtkMeshSignedDistance::DistanceSettings() const
{
  shrinkwrap::SignedDistanceSettings settings;
  settings.sweep =
    this->SweepMethod == EIKONAL ? shrinkwrap::SweepMethod::Eikonal : shrinkwrap::SweepMethod::ClosestPoint;
  settings.bandLayers = this->BandLayers;
  settings.computeSign = this->ComputeSign;
  return settings;
}

bool vtkMeshSignedDistance::Compute(const shrinkwrap::TriangleSoup& soup, const shrinkwrap::TriangleSoup& cloud,
  const shrinkwrap::GridLattice& lattice, int first, int last, const shrinkwrap::SlabExchange* exchange,
  vtkFloatArray* values, shrinkwrap::SignedDistanceResult& result)
{
  const shrinkwrap::SignedDistanceSettings settings = this->DistanceSettings();
  // Under MPI, what must fit is this rank's piece (with a few planes around it), not the grid.
  const shrinkwrap::GridLattice planes = shrinkwrap::planesOf(lattice, first, last);
  const int halo = exchange ? settings.bandLayers + 2 : 0;
  const shrinkwrap::Status fits = shrinkwrap::checkMemory(
    shrinkwrap::planesOf(lattice, std::max(0, first - halo), std::min(lattice.dims[2] - 1, last + halo)), settings);
  if (!fits)
  {
    vtkErrorMacro("Cannot compute the field: " << fits.message() << "; lower Resolution or raise CellSize"
                                               << (exchange ? ", or run on more MPI ranks." : "."));
  }
  if (exchange && !shrinkwrap::everyProcess(*exchange, static_cast<bool>(fits)))
  {
    if (fits)
    {
      vtkErrorMacro("Cannot compute the field: another MPI rank cannot (see its error).");
    }
    return false;
  }
  if (!fits)
  {
    return false;
  }
  values->SetName("SignedDistance");
  const shrinkwrap::Progress progress([this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  });
  try // the memory estimate can be beaten by a process limit (ulimit -v, a job's cap)
  {
    if (!values->SetNumberOfValues(planes.nodeCount()))
    {
      throw std::bad_alloc();
    }
    shrinkwrap::onAllCores([&] {
      float* distance = values->GetPointer(0);
      if (exchange)
      {
        const shrinkwrap::Status status = shrinkwrap::computeSlabDistance(
          soup, cloud.points, lattice, first, last, settings, *exchange, distance, result, progress);
        if (!status)
        {
          throw std::runtime_error(status.message());
        }
      }
      else if (cloud.points.empty())
        result = shrinkwrap::computeSignedDistance(soup, lattice, settings, distance, progress);
      else if (soup.triangles.empty())
        result = shrinkwrap::computePointDistance(cloud.points, lattice, settings, distance, progress);
      else
        result = shrinkwrap::computeUnionDistance(soup, cloud.points, lattice, settings, distance, progress);
    });
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory for a " << lattice.dims[0] << " x " << lattice.dims[1] << " x "
                                         << lattice.dims[2] << " grid: the process may not allocate it; lower "
                                            "Resolution or raise CellSize.");
    return false;
  }
  catch (const std::exception& e) // e.g. threads that cannot start under the same limits
  {
    vtkErrorMacro("Mesh Signed Distance failed: " << e.what() << ".");
    return false;
  }
  if (!result.completed)
  {
    this->AbortExecute = 0; // the abort ends this run; the next update after a change runs normally
    vtkWarningMacro("Mesh Signed Distance was aborted; the output is empty.");
    return false;
  }
  return true;
}

void vtkMeshSignedDistance::AddStatus(const shrinkwrap::SignedDistanceResult& result, vtkImageData* output)
{
  std::ostringstream status;
  status << shrinkwrap::signStatus(result, this->ComputeSign != 0);
  if (shrinkwrap::signNeedsWarning(result, this->ComputeSign != 0))
  {
    vtkWarningMacro("The distance field is " << status.str() << ".");
  }
  vtkNew<vtkIntArray> isSigned;
  isSigned->SetName("Signed");
  isSigned->InsertNextValue(result.isSigned ? 1 : 0);
  vtkNew<vtkStringArray> statusArray;
  statusArray->SetName("DistanceStatus");
  statusArray->InsertNextValue(status.str());
  output->GetFieldData()->AddArray(isSigned);
  output->GetFieldData()->AddArray(statusArray);
}

void vtkMeshSignedDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputGeometry: " << convert::geometryName(this->InputGeometry) << "\n";
  os << indent << "BoxScale: " << this->BoxScale << "\n";
  os << indent << "OffsetFactor: " << this->OffsetFactor << "\n";
  os << indent << "GridCellSize: " << this->GridCellSize << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CellSize: " << this->CellSize << "\n";
  os << indent << "UseExplicitGrid: " << this->UseExplicitGrid << "\n";
  os << indent << "OutputBounds: " << this->OutputBounds[0] << " " << this->OutputBounds[1] << " "
     << this->OutputBounds[2] << " " << this->OutputBounds[3] << " " << this->OutputBounds[4] << " "
     << this->OutputBounds[5] << "\n";
  os << indent << "OutputDimensions: " << this->OutputDimensions[0] << " " << this->OutputDimensions[1] << " "
     << this->OutputDimensions[2] << "\n";
  os << indent << "SweepMethod: " << (this->SweepMethod == EIKONAL ? "Eikonal" : "ClosestPoint") << "\n";
  os << indent << "BandLayers: " << this->BandLayers << "\n";
  os << indent << "ComputeSign: " << this->ComputeSign << "\n";
  os << indent << "FieldPerBlock: " << this->FieldPerBlock << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
