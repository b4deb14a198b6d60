#include "vtkMeshSignedDistance.h"

#include "Common/Parallel.h"
#include "Distance/SignedDistance.h"
#include "Distance/SlabDistance.h"
#include "VTKConversions.h"
#include "RankInputs.h"
#include "SlabPieces.h"
#include "TargetInput.h"
#include "vtkInputGeometry.h"

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
// Ghost layers, when asked for (a contour or gradient across piece borders): the nodes beyond the
// piece proper (as the pipeline's extent translator splits the grid) are marked, so that their
// cells are not counted twice.
void markGhosts(const shrinkwrap::GridLattice& lattice, vtkInformation* outInfo, vtkImageData* output)
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

// The input as this filter measures it.
struct vtkMeshSignedDistance::Measured
{
  shrinkwrap::TriangleSoup soup;  // its triangles (none: points only)
  shrinkwrap::TriangleSoup cloud; // its points (none: polygons only), as the cloud's points
  shrinkwrap::GridLattice lattice;
};

bool vtkMeshSignedDistance::Measure(vtkDataObject* input, Measured& measured)
{
  shrinkwrap::Box bounds;
  if (!this->ReadInput(input, measured.soup, measured.cloud, bounds))
  {
    return false;
  }
  if (const shrinkwrap::Status placed = this->ComputeLattice(bounds, measured.lattice); !placed)
  {
    vtkErrorMacro("Cannot place the grid: " << placed.message() << ".");
    return false;
  }
  return true;
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
  vtkDataObject* input =
    convert::wholeInput(vtkDataObject::GetData(inputVector[0], 0), this->Controller, this->Gathered);
  Measured measured;
  const bool ready = this->Measure(input, measured);
  const shrinkwrap::GridLattice& lattice = measured.lattice;
  int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  const bool byPieces = this->ByPieces(outInfo);
  if (byPieces ? !this->ComputePieces(ready, measured, outInfo, extent, values, result)
               : !ready || !this->Compute(measured, 0, lattice.dims[2] - 1, nullptr, values, result))
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
  if (byPieces && outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) > 0)
  {
    markGhosts(lattice, outInfo, output);
  }
  this->AddStatus(result, output);
  return 1;
}

// Under MPI with a piece per rank, this rank computes an even share of the grid's planes with the
// others (SlabDistance.h), and the ranks then hand each other what their pieces hold.
bool vtkMeshSignedDistance::ByPieces(vtkInformation* outInfo) const
{
  vtkMultiProcessController* controller = this->Controller;
  return controller && controller->GetNumberOfProcesses() > 1 &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) ==
    controller->GetNumberOfProcesses() &&
    this->SweepMethod == CLOSEST_POINT && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT());
}

// This rank's piece (its update extent, into `extent`), computed with the other ranks. Collective:
// every rank must measure the same surface on the same grid, and one that cannot, or holds another
// input, stops all of them (rather than leave the others waiting for it).
bool vtkMeshSignedDistance::ComputePieces(bool ready, const Measured& measured,
  vtkInformation* outInfo, int extent[6], vtkFloatArray* values,
  shrinkwrap::SignedDistanceResult& result)
{
  const convert::ControllerExchange exchange(this->Controller);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const convert::Agreement agreement = convert::agree(
    exchange, ready, measured.soup, measured.cloud.points.size(), measured.lattice, extent);
  if (!agreement.why.empty())
  {
    vtkErrorMacro("Cannot compute the field by pieces: " << agreement.why);
    return false;
  }
  if (!ready)
  {
    return false;
  }
  if (agreement.slabs) // slabs of whole planes (the split this filter asks for): each its own
  {
    return this->Compute(measured, extent[4], extent[5], &exchange, values, result);
  }
  // Pieces of other shapes (a consumer that splits otherwise): even shares of planes, handed round.
  const int rank = this->Controller->GetLocalProcessId();
  const convert::Extent share =
    convert::evenSlab(measured.lattice, rank, this->Controller->GetNumberOfProcesses());
  vtkNew<vtkFloatArray> slab;
  if (!this->Compute(measured, share[4], share[5], &exchange, slab, result))
  {
    return false;
  }
  convert::piecesFromSlabs(this->Controller, measured.lattice, slab, extent, values);
  return true;
}

bool vtkMeshSignedDistance::FieldOf(vtkDataObject* input, vtkImageData* output)
{
  Measured measured;
  if (!this->Measure(input, measured))
  {
    return true;
  }
  const shrinkwrap::GridLattice& lattice = measured.lattice;
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  if (!this->Compute(measured, 0, lattice.dims[2] - 1, nullptr, values, result))
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
  convert::TargetParts parts;
  shrinkwrap::Notes notes;
  shrinkwrap::Status status =
    convert::readTarget(data, this->InputGeometry, { "input", "measured" }, parts, notes);
  this->Report(notes);
  if (status && parts.use.polygons)
  {
    status = shrinkwrap::checkSoup(parts.polygons);
  }
  if (status && parts.use.points && !(parts.use.polygons && parts.points.empty()))
  {
    status = shrinkwrap::checkPoints(parts.points); // beside polygons, there may be none
  }
  if (!status)
  {
    vtkErrorMacro("Cannot measure distances: " << status.message() << ".");
    return false;
  }
  soup = std::move(parts.polygons);
  bounds = parts.polygonBounds;
  cloud = shrinkwrap::TriangleSoup();
  cloud.points.assign(parts.points.begin(), parts.points.end());
  if (!cloud.points.empty())
  {
    vtkOutputWindowDisplayText(
      ("Mesh Signed Distance: the field is the unsigned distance to the nearest of " +
        std::string(parts.use.polygons ? "the input's polygons and " : "its ") +
        std::to_string(cloud.points.size()) +
        (parts.use.polygons ? " points beside them" : " points") +
        (this->InputGeometry == vtkInputGeometry::AUTOMATIC ? " (it has no polygons)" : "") + ".\n")
        .c_str());
    bounds.extend(shrinkwrap::Box::around(cloud.points));
  }
  return true;
}

void vtkMeshSignedDistance::Report(const shrinkwrap::Notes& notes)
{
  for (const shrinkwrap::Note& note : notes)
  {
    if (note.kind == shrinkwrap::Note::Warning)
    {
      vtkWarningMacro(<< note.text << ".");
    }
    else
    {
      vtkOutputWindowDisplayText(("Mesh Signed Distance: " + note.text + ".\n").c_str());
    }
  }
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

bool vtkMeshSignedDistance::Compute(const Measured& measured, int first, int last,
  const shrinkwrap::SlabExchange* exchange, vtkFloatArray* values,
  shrinkwrap::SignedDistanceResult& result)
{
  const shrinkwrap::TriangleSoup& soup = measured.soup;
  const shrinkwrap::TriangleSoup& cloud = measured.cloud;
  const shrinkwrap::GridLattice& lattice = measured.lattice;
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
