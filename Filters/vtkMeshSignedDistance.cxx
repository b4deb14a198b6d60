#include "vtkMeshSignedDistance.h"

#include "Parallel.h"
#include "SignedDistance.h"
#include "VTKConversions.h"

#include "vtkAlgorithmOutput.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <new>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkMeshSignedDistance);

namespace convert = shrinkwrap::convert;

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
}

int vtkMeshSignedDistance::FillInputPortInformation(int, vtkInformation* info)
{
  // Composite inputs are taken whole (one field of all their meshes): left to the composite pipeline,
  // they would run once per block.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
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
  shrinkwrap::Box bounds;
  if (!this->UseExplicitGrid && this->GetNumberOfInputConnections(0) > 0)
  {
    vtkAlgorithm* producer = this->GetInputAlgorithm(0, 0);
    const int port = this->GetInputConnection(0, 0)->GetIndex();
    producer->UpdatePiece(0, 1, 0);
    vtkDataObject* input = producer->GetOutputDataObject(port);
    // The bounds of what ReadInput will measure.
    const shrinkwrap::Box polygons = convert::surfaceBounds(convert::polygonMeshes(input).meshes);
    const convert::Geometry use = convert::chooseGeometry(this->InputGeometry, !polygons.empty());
    if (use.polygons)
    {
      bounds.extend(polygons);
    }
    if (use.points)
    {
      bounds.extend(shrinkwrap::Box::around(convert::pointsOf(input)));
    }
  }
  shrinkwrap::GridLattice lattice;
  this->GridCellSize = 0;
  if (this->ComputeLattice(bounds, lattice))
  {
    this->GridCellSize = lattice.spacing.maxCoeff();
    const int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    outInfo->Set(vtkDataObject::ORIGIN(), lattice.origin.data(), 3);
    outInfo->Set(vtkDataObject::SPACING(), lattice.spacing.data(), 3);
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
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();
  shrinkwrap::TriangleSoup soup, cloud;
  shrinkwrap::Box bounds;
  shrinkwrap::GridLattice lattice;
  if (!this->ReadInput(vtkDataObject::GetData(inputVector[0], 0), soup, cloud, bounds))
  {
    return 1;
  }
  if (const shrinkwrap::Status placed = this->ComputeLattice(bounds, lattice); !placed)
  {
    vtkErrorMacro("Cannot place the grid: " << placed.message() << ".");
    return 1;
  }
  vtkNew<vtkFloatArray> values;
  shrinkwrap::SignedDistanceResult result;
  if (!this->Compute(soup, cloud, lattice, values, result))
  {
    return 1;
  }
  int extent[6] = { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
  output->SetExtent(extent);
  output->SetOrigin(lattice.origin.data());
  output->SetSpacing(lattice.spacing.data());
  output->GetPointData()->SetScalars(values);
  // A downstream request for part of the grid (streaming, or a piece per MPI rank) gets that part.
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    output->Crop(extent);
  }
  this->AddStatus(result, output);
  return 1;
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
        const std::vector<shrinkwrap::Vec3> loose = convert::loosePointsOf(mesh);
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
      cloud.points = convert::pointsOf(data);
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
  const shrinkwrap::GridLattice& lattice, vtkFloatArray* values, shrinkwrap::SignedDistanceResult& result)
{
  const shrinkwrap::SignedDistanceSettings settings = this->DistanceSettings();
  if (const shrinkwrap::Status fits = shrinkwrap::checkMemory(lattice, settings); !fits)
  {
    vtkErrorMacro("Cannot compute the field: " << fits.message() << "; lower Resolution or raise CellSize.");
    return false;
  }
  values->SetName("SignedDistance");
  const shrinkwrap::Progress progress([this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  });
  try // the memory estimate can be beaten by a process limit (ulimit -v, a job's cap)
  {
    if (!values->SetNumberOfValues(lattice.nodeCount()))
    {
      throw std::bad_alloc();
    }
    shrinkwrap::onAllCores([&] {
      float* distance = values->GetPointer(0);
      if (cloud.points.empty())
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
}
