#include "vtkMeshSignedDistance.h"

#include "AllCores.h"
#include "SignedDistance.h"
#include "SystemMemory.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTriangleStrip.h"

#include <algorithm>
#include <new>
#include <cstdlib>
#include <sstream>

vtkStandardNewMacro(vtkMeshSignedDistance);

namespace
{
using shrinkwrap::TriangleSoup;

// The polygon meshes of the input: itself, or the leaves of a composite dataset (one field of them
// all). A leaf with cells that are not polygons is an error: Extract Surface makes polygons of it.
bool polygonMeshes(vtkDataObject* input, std::vector<vtkPolyData*>& meshes, std::string& error)
{
  meshes.clear();
  for (vtkDataSet* leaf : vtkCompositeDataSet::GetDataSets(input))
  {
    if (auto* mesh = vtkPolyData::SafeDownCast(leaf))
    {
      meshes.push_back(mesh);
    }
    else if (leaf->GetNumberOfCells() > 0)
    {
      error = std::string("a block of the input is a ") + leaf->GetClassName() +
        ", not a polygon mesh; apply Extract Surface to it first";
      return false;
    }
  }
  return true;
}

// Appends a mesh to the paper's triangle soup: polygons of any size (ear-cut by vtkPolygon when
// n > 3) and strips. Cells naming points that do not exist are counted in badCells and left out.
void appendToSoup(vtkPolyData* input, TriangleSoup& soup, vtkIdType& badCells)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  const vtkIdType first = static_cast<vtkIdType>(soup.points.size());
  soup.points.resize(first + np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->GetPoint(i, soup.points[first + i].data());
  }
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    soup.triangles.push_back(
      { static_cast<int>(first + a), static_cast<int>(first + b), static_cast<int>(first + c) });
  };
  auto valid = [&](vtkIdType n, const vtkIdType* ids) {
    const bool ok = std::all_of(ids, ids + n, [np](vtkIdType id) { return id >= 0 && id < np; });
    badCells += !ok;
    return ok;
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> corners;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCurrentCell(n, ids);
    if (!valid(n, ids))
    {
      continue;
    }
    if (n == 3)
    {
      addTriangle(ids[0], ids[1], ids[2]);
      continue;
    }
    if (n < 3)
    {
      continue;
    }
    polygon->Initialize(n, ids, points);
    if (polygon->Triangulate(corners) && corners->GetNumberOfIds() > 0)
    {
      for (vtkIdType k = 0; k + 2 < corners->GetNumberOfIds(); k += 3)
      {
        addTriangle(ids[corners->GetId(k)], ids[corners->GetId(k + 1)], ids[corners->GetId(k + 2)]);
      }
    }
    else
    {
      // Ear cutting fails on degenerate polygons; a fan still has their distances.
      for (vtkIdType k = 1; k + 1 < n; ++k)
      {
        addTriangle(ids[0], ids[k], ids[k + 1]);
      }
    }
  }
  vtkNew<vtkCellArray> stripTriangles;
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    strips->GetCurrentCell(n, ids);
    if (!valid(n, ids))
    {
      continue;
    }
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      // Strips alternate orientation.
      k % 2 == 0 ? addTriangle(ids[k], ids[k + 1], ids[k + 2]) : addTriangle(ids[k + 1], ids[k], ids[k + 2]);
    }
  }
}

// Bounds of the points that polygons and strips use: the surface, without stray points or lines.
void extendBySurface(vtkPolyData* input, shrinkwrap::Box& box)
{
  vtkPoints* points = input->GetPoints();
  if (!points)
  {
    return;
  }
  const vtkIdType np = points->GetNumberOfPoints();
  for (vtkCellArray* cells : { input->GetPolys(), input->GetStrips() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] >= 0 && ids[k] < np)
        {
          shrinkwrap::Vec3 p;
          points->GetPoint(ids[k], p.data());
          box.extend(p);
        }
      }
    }
  }
}

shrinkwrap::Box surfaceBounds(const std::vector<vtkPolyData*>& meshes)
{
  shrinkwrap::Box box;
  for (vtkPolyData* mesh : meshes)
  {
    extendBySurface(mesh, box);
  }
  return box;
}

std::string gibibytes(double bytes)
{
  std::ostringstream s;
  s.precision(3);
  s << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return s.str();
}

} // namespace

vtkMeshSignedDistance::vtkMeshSignedDistance()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkMeshSignedDistance::FillInputPortInformation(int, vtkInformation* info)
{
  // Composite inputs are taken whole (one field of all their meshes): left to the composite pipeline,
  // they would run once per block.
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

bool vtkMeshSignedDistance::ComputeLattice(
  const shrinkwrap::Box& surfaceBounds, shrinkwrap::GridLattice& lattice, std::string& error) const
{
  if (this->UseExplicitGrid)
  {
    shrinkwrap::Box box; // as given: inverted bounds are an error, not swapped
    box.min = shrinkwrap::Vec3(this->OutputBounds[0], this->OutputBounds[2], this->OutputBounds[4]);
    box.max = shrinkwrap::Vec3(this->OutputBounds[1], this->OutputBounds[3], this->OutputBounds[5]);
    return shrinkwrap::explicitGrid(
      box, { this->OutputDimensions[0], this->OutputDimensions[1], this->OutputDimensions[2] }, lattice, error);
  }
  const shrinkwrap::GridPlacement placement{ this->BoxScale, this->OffsetFactor, this->Resolution, this->CellSize };
  return shrinkwrap::placeGrid(surfaceBounds, placement, lattice, error);
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
    std::vector<vtkPolyData*> meshes;
    std::string ignored; // RequestData reports it
    if (polygonMeshes(producer->GetOutputDataObject(port), meshes, ignored))
    {
      bounds = surfaceBounds(meshes);
    }
  }
  shrinkwrap::GridLattice lattice;
  std::string error;
  if (this->ComputeLattice(bounds, lattice, error))
  {
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
  std::vector<vtkPolyData*> meshes;
  std::string error;
  if (!polygonMeshes(vtkDataObject::GetData(inputVector[0], 0), meshes, error))
  {
    vtkErrorMacro("Mesh Signed Distance needs polygon meshes: " << error << ".");
    return 1;
  }

  // Input checks: each leaves an empty output and the pipeline usable.
  vtkIdType lines = 0, verts = 0, badCells = 0;
  TriangleSoup soup;
  for (vtkPolyData* mesh : meshes)
  {
    lines += mesh->GetNumberOfLines();
    verts += mesh->GetNumberOfVerts();
    appendToSoup(mesh, soup, badCells);
  }
  if (lines > 0 || verts > 0)
  {
    vtkWarningMacro("Ignoring " << lines << " lines and " << verts
                                << " vertices: only polygons and triangle strips have an inside.");
  }
  if (badCells > 0)
  {
    vtkErrorMacro("The input has " << badCells << " cells whose point ids are out of range: it is corrupt.");
    return 1;
  }
  if (soup.triangles.empty())
  {
    vtkErrorMacro("The input has no polygons or triangle strips: there is no surface to measure from.");
    return 1;
  }
  if (!soup.allFinite())
  {
    vtkErrorMacro("The input has NaN or infinite point coordinates; fix or remove those points first.");
    return 1;
  }
  if (!shrinkwrap::withinCoordinateRange(soup.bounds()))
  {
    vtkErrorMacro("The input has coordinates beyond +-1e30, which distances in float cannot hold; "
                  "scale or translate it first.");
    return 1;
  }
  if (!(soup.maxTriangleArea() > 0))
  {
    vtkErrorMacro("Every triangle of the input is degenerate (zero area): there is no surface.");
    return 1;
  }

  shrinkwrap::GridLattice lattice;
  if (!this->ComputeLattice(surfaceBounds(meshes), lattice, error))
  {
    vtkErrorMacro("Cannot place the grid: " << error << ".");
    return 1;
  }

  shrinkwrap::SignedDistanceSettings settings;
  settings.sweep =
    this->SweepMethod == EIKONAL ? shrinkwrap::SweepMethod::Eikonal : shrinkwrap::SweepMethod::ClosestPoint;
  settings.bandLayers = this->BandLayers;
  settings.computeSign = this->ComputeSign;

  // Refuse a grid that cannot fit before allocating anything for it.
  // In floating point: the node count of an absurd grid overflows 64-bit integers.
  const double nodes = static_cast<double>(lattice.dims[0]) * lattice.dims[1] * lattice.dims[2];
  const double needed = nodes * (sizeof(float) + shrinkwrap::workingBytesPerNode(settings));
  const double available = static_cast<double>(shrinkwrap::availableMemoryBytes());
  if (needed > 0.8 * available)
  {
    vtkErrorMacro("A " << lattice.dims[0] << " x " << lattice.dims[1] << " x " << lattice.dims[2]
                       << " grid would need " << gibibytes(needed) << " but only " << gibibytes(available)
                       << " of memory is available; lower Resolution or raise CellSize.");
    return 1;
  }

  vtkNew<vtkFloatArray> values;
  values->SetName("SignedDistance");
  shrinkwrap::SignedDistanceResult result;
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
      result = shrinkwrap::computeSignedDistance(soup, lattice, settings, values->GetPointer(0), progress);
    });
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Out of memory for a " << lattice.dims[0] << " x " << lattice.dims[1] << " x "
                                         << lattice.dims[2] << " grid (" << gibibytes(needed)
                                         << " estimated): the process may not allocate it; lower Resolution "
                                            "or raise CellSize.");
    return 1;
  }
  catch (const std::exception& e) // e.g. threads that cannot start under the same limits
  {
    vtkErrorMacro("Mesh Signed Distance failed: " << e.what() << ".");
    return 1;
  }
  if (!result.completed)
  {
    this->AbortExecute = 0; // the abort ends this run; the next update after a change runs normally
    vtkWarningMacro("Mesh Signed Distance was aborted; the output is empty.");
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

  std::ostringstream status;
  if (result.isSigned)
  {
    status << "signed";
    if (result.invertedOrientation)
    {
      status << " (the triangles face inwards; the signs follow the geometry)";
      vtkWarningMacro("The mesh's triangles face inwards; the signs follow the geometry (negative inside).");
    }
  }
  else if (!this->ComputeSign)
  {
    status << "unsigned: ComputeSign is off";
  }
  else
  {
    status << "unsigned: the outside reaches the inside (" << result.boundaryEdges << " boundary edges, "
           << result.nonManifoldEdges << " non-manifold edges, " << result.signDisagreements
           << " band sign disagreements)";
    vtkWarningMacro("The mesh is not closed, so the distance field is " << status.str() << ".");
  }
  vtkNew<vtkIntArray> isSigned;
  isSigned->SetName("Signed");
  isSigned->InsertNextValue(result.isSigned ? 1 : 0);
  vtkNew<vtkStringArray> statusArray;
  statusArray->SetName("DistanceStatus");
  statusArray->InsertNextValue(status.str());
  output->GetFieldData()->AddArray(isSigned);
  output->GetFieldData()->AddArray(statusArray);
  return 1;
}

void vtkMeshSignedDistance::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BoxScale: " << this->BoxScale << "\n";
  os << indent << "OffsetFactor: " << this->OffsetFactor << "\n";
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
