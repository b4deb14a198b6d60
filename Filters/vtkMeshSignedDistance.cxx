#include "vtkMeshSignedDistance.h"

#include "Common/Parallel.h"
#include "Distance/SignedDistance.h"
#include "Distance/SlabDistance.h"
#include "FieldRun.h"
#include "MeshSignedDistanceProperties.h"
#include "PropertyBinding.h"
#include "RankInputs.h"
#include "SlabPieces.h"
#include "TargetInput.h"
#include "VTKConversions.h"
#include "vtkInputGeometry.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExtentTranslator.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMeshSignedDistance);

std::vector<convert::PropertyInfo> vtkMeshSignedDistance::DescribeProperties()
{
  std::vector<convert::PropertyInfo> described{ kInputGeometry, kUseExplicitGrid, kOutputBounds,
    kOutputDimensions, kFieldPerBlock };
  const FieldSettings settings;
  vtkNew<vtkMeshSignedDistance> filter;
  BindProperties(*filter.Get(), settings,
    [&](const convert::PropertyInfo& p, const auto&, const auto&) { described.push_back(p); });
  return described;
}

shrinkwrap::Status vtkMeshSignedDistance::CheckProperties() const
{
  shrinkwrap::Status status = convert::checkProperty(kInputGeometry, this->InputGeometry);
  if (status && this->UseExplicitGrid)
  {
    status = convert::checkProperty(kOutputBounds, this->OutputBounds);
  }
  if (status && this->UseExplicitGrid)
  {
    status = convert::checkProperty(kOutputDimensions, this->OutputDimensions);
  }
  const FieldSettings unused;
  BindProperties(
    *this, unused, [&](const convert::PropertyInfo& info, const auto& property, const auto&) {
      if (status)
      {
        status = convert::checkProperty(info, property);
      }
    });
  return status;
}

vtkMeshSignedDistance::vtkMeshSignedDistance()
{
  const FieldSettings defaults; // stated once, in the core's settings
  BindProperties(
    *this, defaults, [](const convert::PropertyInfo&, auto& property, const auto& setting) {
      convert::assign(property, setting);
    });
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
  // Composite inputs are taken whole (one field of all their meshes): left to the composite
  // pipeline, they would run once per block.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

vtkTypeBool vtkMeshSignedDistance::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // FieldPerBlock with a composite input gives a composite of the same kind (a field per block),
  // anything else an image.
  vtkCompositeDataSet* blocks =
    this->FieldPerBlock ? vtkCompositeDataSet::GetData(inputVector[0], 0) : nullptr;
  return convert::makeOutput<vtkImageData>(request, outputVector, blocks) ||
    this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

shrinkwrap::Status vtkMeshSignedDistance::ComputeLattice(
  const shrinkwrap::Box& surfaceBounds, shrinkwrap::GridLattice& lattice) const
{
  if (this->UseExplicitGrid)
  {
    shrinkwrap::Box box; // as given: inverted bounds are an error, not swapped
    box.min = shrinkwrap::Vec3(this->OutputBounds[0], this->OutputBounds[2], this->OutputBounds[4]);
    box.max = shrinkwrap::Vec3(this->OutputBounds[1], this->OutputBounds[3], this->OutputBounds[5]);
    return shrinkwrap::explicitGrid(box,
      { this->OutputDimensions[0], this->OutputDimensions[1], this->OutputDimensions[2] }, lattice);
  }
  return shrinkwrap::placeGrid(surfaceBounds, this->CoreSettings().placement, lattice);
}

int vtkMeshSignedDistance::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Downstream filters (slices, contours, streaming) need the grid now. A grid placed around the
  // input needs the input's bounds, so the input is brought up to date here; RequestData derives
  // the same lattice from the same bounds.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  this->GridCellSize = 0;
  if (!this->CheckProperties())
  {
    return 1; // RequestData says why
  }
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
    vtkDataObject* input =
      convert::wholeInput(producer->GetOutputDataObject(port), this->Controller, this->Gathered);
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
    const int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0,
      lattice.dims[2] - 1 };
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
  convert::askWholeInputs(inputVector, 1, false); // distances need the whole mesh
  return 1;
}

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
  if (const shrinkwrap::Status checked = this->CheckProperties(); !checked)
  {
    vtkDataObject::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT()))->Initialize();
    vtkErrorMacro("Cannot compute the field: " << checked.message() << ".");
    return 1;
  }
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    this->ExecuteBlocks(vtkCompositeDataSet::GetData(inputVector[0], 0), outInfo, blocks);
    return 1;
  }
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  vtkDataObject* input = convert::wholeInput(
    vtkDataObject::GetData(inputVector[0], 0), this->Controller, this->Gathered);
  Measured measured;
  const bool ready = this->Measure(input, measured);
  const shrinkwrap::GridLattice& lattice = measured.lattice;
  int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  const bool byPieces = this->ByPieces(outInfo);
  const bool computed = byPieces
    ? this->Computed(
        convert::computePieces(this->Controller, ready, measured, this->CoreSettings().distance,
          this->ProgressOf(), outInfo, extent, values, result),
        result)
    : ready && this->Compute(measured, 0, lattice.dims[2] - 1, values, result);
  if (!computed)
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
  if (byPieces &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()) > 0)
  {
    convert::markGhosts(lattice, outInfo, output);
  }
  convert::report(
    this, "Mesh Signed Distance", convert::addSignStatus(result, this->ComputeSign, output));
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
    this->SweepMethod == CLOSEST_POINT &&
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT());
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
  if (!this->Compute(measured, 0, lattice.dims[2] - 1, values, result))
  {
    return false;
  }
  output->SetDimensions(lattice.dims.data());
  output->SetOrigin(lattice.origin.data());
  output->SetSpacing(lattice.spacing.data());
  output->GetPointData()->SetScalars(values);
  convert::report(
    this, "Mesh Signed Distance", convert::addSignStatus(result, this->ComputeSign, output));
  return true;
}

// Each block's field is computed whole in one process; under MPI the blocks are shared out among
// the pieces by their grids' nodes, or computed where they are when the composite arrives
// distributed (the other pieces leave a block empty).
void vtkMeshSignedDistance::ExecuteBlocks(
  vtkCompositeDataSet* input, vtkInformation* outInfo, vtkCompositeDataSet* output)
{
  output->Initialize();
  const convert::PieceRequest request = convert::pieceRequest(outInfo);
  const std::vector<vtkDataSet*> leaves = convert::leavesOf(input);
  const std::vector<int> computedOn =
    convert::piecesOfLeaves(input, leaves, request, this->Controller, [&] {
      std::vector<double> nodes; // the cost of a block's field
      for (vtkDataSet* leaf : leaves)
      {
        shrinkwrap::GridLattice lattice;
        const bool placed = leaf && this->ComputeLattice(convert::boundsOf(leaf), lattice);
        nodes.push_back(placed ? static_cast<double>(lattice.nodeCount()) : 1.0);
      }
      return convert::shareOut(nodes, request.pieces);
    });
  bool goOn = true; // until a run is aborted or runs out of memory
  convert::computeLeaves<vtkImageData>(input, output, computedOn, request.piece,
    [&](vtkDataSet* leaf, unsigned int, vtkImageData* field, double first, double share) {
      this->SetProgressShiftScale(first, share); // one progress bar over the blocks
      goOn = goOn && this->FieldOf(leaf, field);
    });
  this->SetProgressShiftScale(0, 1);
}

bool vtkMeshSignedDistance::ReadInput(vtkDataObject* data, shrinkwrap::TriangleSoup& soup,
  shrinkwrap::TriangleSoup& cloud, shrinkwrap::Box& bounds)
{
  convert::TargetParts parts;
  shrinkwrap::Notes notes;
  shrinkwrap::Status status =
    convert::readTarget(data, this->InputGeometry, { "input", "measured" }, parts, notes);
  convert::report(this, "Mesh Signed Distance", notes);
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
    const bool beside = parts.use.polygons;
    vtkOutputWindowDisplayText(
      ("Mesh Signed Distance: the field is the unsigned distance to the nearest of " +
        std::string(beside ? "the input's polygons and " : "its ") +
        std::to_string(cloud.points.size()) + (beside ? " points beside them" : " points") +
        (this->InputGeometry == vtkInputGeometry::AUTOMATIC ? " (it has no polygons)" : "") + ".\n")
        .c_str());
    bounds.extend(shrinkwrap::Box::around(cloud.points));
  }
  return true;
}

vtkMeshSignedDistance::FieldSettings vtkMeshSignedDistance::CoreSettings() const
{
  FieldSettings settings;
  BindProperties(
    *this, settings, [](const convert::PropertyInfo&, const auto& property, auto& setting) {
      convert::assign(setting, property);
    });
  return settings;
}

// The distances at planes first .. last (convert::computeField); false (reported) when they could
// not be computed or the run was aborted.
bool vtkMeshSignedDistance::Compute(const Measured& measured, int first, int last,
  vtkFloatArray* values, shrinkwrap::SignedDistanceResult& result)
{
  const shrinkwrap::Status status = convert::computeField(measured, first, last, nullptr,
    this->CoreSettings().distance, this->ProgressOf(), values, result);
  return this->Computed(status, result);
}

bool vtkMeshSignedDistance::Computed(
  const shrinkwrap::Status& status, const shrinkwrap::SignedDistanceResult& result)
{
  if (!status)
  {
    vtkErrorMacro(<< status.message() << ".");
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

shrinkwrap::Progress vtkMeshSignedDistance::ProgressOf()
{
  return shrinkwrap::Progress([this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  });
}

int vtkMeshSignedDistance::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject"); // an image, or a composite of them
  return 1;
}

void vtkMeshSignedDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const auto print = convert::propertyPrinter(os, indent);
  print(convert::PropertyInfo{ "InputGeometry", "", "" },
    convert::geometryName(this->InputGeometry), 0);
  print(convert::PropertyInfo{ "UseExplicitGrid", "", "" }, this->UseExplicitGrid, 0);
  print(convert::PropertyInfo{ "OutputBounds", "", "" }, this->OutputBounds, 0);
  print(convert::PropertyInfo{ "OutputDimensions", "", "" }, this->OutputDimensions, 0);
  const FieldSettings unused;
  BindProperties(*this, unused, print);
  os << indent << "GridCellSize: " << this->GridCellSize << "\n";
  os << indent << "FieldPerBlock: " << this->FieldPerBlock << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
