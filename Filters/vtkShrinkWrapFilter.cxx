#include "vtkShrinkWrapFilter.h"

#include "Common/Parallel.h"
#include "Distance/PointSource.h"
#include "Surface/SelfIntersections.h"
#include "Distance/SignedDistance.h"
#include "Distance/UnionSource.h"
#include "VTKConversions.h"
#include "RankInputs.h"
#include "Evolution/WrapSession.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShrinkWrapFilter);

using namespace shrinkwrap;

namespace
{
// A composite among port 0's inputs, if there is one: the target, wrapped block by block.
vtkCompositeDataSet* compositeTarget(vtkInformationVector* port0)
{
  for (int c = 0; c < port0->GetNumberOfInformationObjects(); ++c)
  {
    if (auto* composite = vtkCompositeDataSet::GetData(port0, c))
    {
      return composite;
    }
  }
  return nullptr;
}

// The piece that wraps each block (convert::shareOut). The cost is the wrap's expected vertex count,
// the block's area over L^2 (its resolved Target Edge Length); 1 for a block without polygons
// (points: no area to go by).
std::vector<int> piecesOfBlocks(const std::vector<vtkDataSet*>& targets, int pieces, const WrapSettings& settings)
{
  std::vector<double> cost(targets.size(), 0);
  for (std::size_t b = 0; b < targets.size(); ++b)
  {
    const convert::PolygonMeshes meshes = convert::polygonMeshes(targets[b]);
    convert::SoupCounts counts;
    const TriangleSoup soup = meshes.meshes.empty() ? TriangleSoup() : convert::soupOf(meshes.meshes, counts);
    double area = 0;
    for (const auto& t : soup.triangles)
    {
      const auto& p = soup.points;
      const bool valid = std::all_of(t.begin(), t.end(), [&](int v) { return v >= 0 && v < static_cast<int>(p.size()); });
      area += valid ? 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm() : 0.0;
    }
    const Box box = convert::boundsOf(targets[b]);
    const double length = box.empty() ? 0.0 : settings.resolved(box).targetLength;
    cost[b] = length > 0 && std::isfinite(area / (length * length)) ? std::max(1.0, area / (length * length)) : 1.0;
  }
  return convert::shareOut(cost, pieces);
}

// The target among port 0's inputs and the distance field, on port 1 or beside the target on port 0
// (an image with SignedDistance there); the number of targets found.
int targetAndField(
  const std::vector<vtkDataObject*>& port0, vtkImageData* port1, vtkDataObject*& target, vtkImageData*& field)
{
  field = port1;
  target = nullptr;
  int targets = 0;
  for (vtkDataObject* data : port0)
  {
    auto* image = vtkImageData::SafeDownCast(data);
    if (image && !field && image->GetPointData()->GetArray("SignedDistance"))
    {
      field = image;
      continue;
    }
    target = data;
    targets += data != nullptr;
  }
  return targets;
}

// The unsigned field of the points (and of the polygons beside them, if given), computed here, and the
// fields of a wrap onto them.
Status pointFields(const PointCloud& cloud, const std::shared_ptr<const TriangleSource>& polygons, bool givenStart,
  const WrapSettings& settings, WrapFields& fields)
{
  const PointSource& points = *cloud.points;
  Box box = points.bounds();
  if (polygons)
  {
    box.extend(polygons->bounds());
  }
  GridLattice lattice;
  Status status = placeGrid(box, settings.fieldPlacement(box, givenStart), lattice);
  if (status)
  {
    status = checkMemory(lattice, SignedDistanceSettings());
  }
  if (!status)
  {
    return Status::failure("the points' distance field: " + status.message());
  }
  std::vector<float> values(lattice.nodeCount());
  if (polygons)
  {
    SignedDistanceSettings unsignedDistance;
    unsignedDistance.computeSign = false;
    computeSignedDistance(UnionSource({ polygons, cloud.points }), lattice, unsignedDistance, values.data());
  }
  else
  {
    computePointDistance(points, lattice, SignedDistanceSettings(), values.data());
  }
  return pointWrapFields(DistanceGrid(lattice, std::move(values)), cloud, settings, fields, polygons);
}

// The points a wrap takes of its target: beside its polygons, the points none of them uses; else all.
PointList wrappedPoints(vtkDataObject* target, vtkPolyData* mesh, const convert::Geometry& use)
{
  return use.polygons ? (mesh ? convert::loosePointsOf<PointList>(mesh) : PointList()) : convert::pointsOf<PointList>(target);
}
} // namespace

vtkShrinkWrapFilter::vtkShrinkWrapFilter()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(1);
  const WrapSettings defaults;
  const EvolverSettings& e = defaults.evolution;
  this->TimeStep = e.timeStep;
  this->NumberOfSteps = defaults.steps;
  this->SubdivisionLevel = defaults.start.subdivision;
  this->C1 = e.C1;
  this->C2 = e.C2;
  this->C = e.C;
  this->D = e.D;
  this->TangentialRedistribution = static_cast<int>(e.redistribution); // NONE, ANGLE, VOLUME in order
  this->OmegaAngle = e.omegaAngle;
  this->OmegaVolume = e.omegaVolume;
  this->RhoA = e.rhoA;
  this->DistanceWeighting = e.distanceWeight;
  this->EdgeFlips = e.edgeFlips;
  this->EdgeCollapses = e.edgeCollapses;
  this->CoverRims = e.rims.cover;
  this->FitFacets = e.facetFit != 0;
  this->CreaseAngle = e.rims.creaseAngle;
  this->FlipDihedralLimit = e.flips.maxDihedral;
  this->StartingShape = static_cast<int>(defaults.start.shape); // ICOSPHERE, OFFSET_SURFACE in order
  this->StartOffset = defaults.start.offset;
  this->GapSize = defaults.gapSize;
  this->CloseHoles = defaults.closeHoles;
  this->Remeshing = defaults.remeshing;
  this->TargetEdgeLength = defaults.targetLength;
  this->EdgeLengthRange[0] = defaults.edgeRange[0];
  this->EdgeLengthRange[1] = defaults.edgeRange[1];
  this->InitialRelaxation = defaults.start.relaxation;
  this->AutomaticScaling = defaults.automaticScaling;
  this->SolverTolerance = e.solverTolerance;
  this->Resolution = defaults.resolution;
  this->CacheMemoryLimit = defaults.cacheMiB;
  this->SetProgressText("Shrink Wrap");
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkShrinkWrapFilter::~vtkShrinkWrapFilter()
{
  this->SetController(nullptr);
}

vtkCxxSetObjectMacro(vtkShrinkWrapFilter, Controller, vtkMultiProcessController);

WrapSettings vtkShrinkWrapFilter::CoreSettings() const
{
  WrapSettings s;
  EvolverSettings& e = s.evolution;
  e.timeStep = this->TimeStep;
  s.steps = this->NumberOfSteps;
  s.start.subdivision = this->SubdivisionLevel;
  e.C1 = this->C1;
  e.C2 = this->C2;
  e.C = this->C;
  e.D = this->D;
  e.redistribution = static_cast<Redistribution>(this->TangentialRedistribution);
  e.omegaAngle = this->OmegaAngle;
  e.omegaVolume = this->OmegaVolume;
  e.rhoA = this->RhoA;
  e.distanceWeight = this->DistanceWeighting;
  e.edgeFlips = this->EdgeFlips;
  e.edgeCollapses = this->EdgeCollapses;
  e.rims.cover = this->CoverRims;
  e.facetFit = this->FitFacets ? 1.0 : 0.0;
  e.rims.creaseAngle = this->CreaseAngle;
  e.flips.maxDihedral = this->FlipDihedralLimit;
  s.start.shape = static_cast<StartShape>(this->StartingShape);
  s.start.offset = this->StartOffset;
  s.gapSize = this->GapSize;
  s.closeHoles = this->CloseHoles;
  s.remeshing = this->Remeshing;
  s.targetLength = this->TargetEdgeLength;
  s.edgeRange = { this->EdgeLengthRange[0], this->EdgeLengthRange[1] };
  s.start.relaxation = this->InitialRelaxation;
  s.automaticScaling = this->AutomaticScaling;
  e.solverTolerance = this->SolverTolerance;
  s.resolution = this->Resolution;
  s.cacheMiB = this->CacheMemoryLimit;
  return s;
}

int vtkShrinkWrapFilter::GetNumberOfComputedSteps() const
{
  int steps = this->Current ? this->Current->computedSteps() : 0;
  for (const auto& block : this->Blocks)
  {
    steps += block.second.session ? block.second.session->computedSteps() : 0;
  }
  return steps;
}

int vtkShrinkWrapFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  const char* types[] = { "vtkDataSet", "vtkImageData", "vtkPolyData" }; // target, field, start
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), types[std::clamp(port, 0, 2)]);
  if (port == 0)
  {
    // A composite target is taken whole and wrapped block by block (ExecuteBlocks): left to the
    // composite pipeline, each block would restart the others' sessions and time would not move.
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1); // the target, and maybe its field (TargetAndField)
  }
  if (port > 0)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkShrinkWrapFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject"); // a surface, or a composite of them
  return 1;
}

vtkTypeBool vtkShrinkWrapFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

// A composite target gives a composite of the same kind (a wrap per block), anything else a surface.
int vtkShrinkWrapFilter::RequestDataObject(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkCompositeDataSet* composite = this->WrapBlocksTogether ? nullptr : compositeTarget(inputVector[0]);
  convert::makeOutput<vtkPolyData>(outputVector->GetInformationObject(0), composite);
  return 1;
}

int vtkShrinkWrapFilter::ComputePipelineMTime(vtkInformation* request, vtkInformationVector** inInfoVec,
  vtkInformationVector* outInfoVec, int requestFromOutputPort, vtkMTimeType* mtime)
{
  const int result =
    this->Superclass::ComputePipelineMTime(request, inInfoVec, outInfoVec, requestFromOutputPort, mtime);
  if (this->RunAgain)
  {
    this->RunAgainTime.Modified();
    this->RunAgain = false;
  }
  *mtime = std::max(*mtime, this->RunAgainTime.GetMTime());
  return result;
}

int vtkShrinkWrapFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Every evolution step is a time step of the output.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int n = this->NumberOfSteps; // clamped by its setter: at most kMaxSteps
  const double tau = this->TimeStep > 0 ? this->TimeStep : 1.0;
  std::vector<double> times(n + 1);
  for (int k = 0; k <= n; ++k)
  {
    times[k] = k * tau;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), n + 1);
  const double range[2] = { 0.0, n * tau };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  onAllCores([&] { this->ShowSizes(this->PlannedSizes(inputVector)); }); // its points' spacing is threaded
  return 1;
}

void vtkShrinkWrapFilter::ShowSizes(const convert::WrapSizes& sizes)
{
  this->FieldCellSize = sizes.cell;
  this->ChosenGapSize = sizes.gap;
  this->ChosenTargetEdgeLength = sizes.length;
}

// ParaView reads information properties after RequestInformation, not after RequestData, so the
// sizes are worked out here from the inputs as they stand (in the GUI the target has been shown by then;
// an update from here would break the composite executive's block-by-block pass): a connected field's
// spacing as its pipeline information gives it, or the field placed as FieldsOf will place it; the
// automatic gap and edge length resolved as StartSession resolves them. 0 while the target has not
// been computed yet; RequestData then sets the run's.
convert::WrapSizes vtkShrinkWrapFilter::PlannedSizes(vtkInformationVector** inputVector)
{
  std::vector<vtkDataObject*> inputs[2];
  for (int port = 0; port < 2; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      inputs[port].push_back(inputVector[port]->GetInformationObject(c)->Get(vtkDataObject::DATA_OBJECT()));
    }
  }
  vtkDataObject* target = nullptr;
  vtkImageData* field = nullptr;
  targetAndField(inputs[0], inputs[1].empty() ? nullptr : vtkImageData::SafeDownCast(inputs[1][0]), target, field);
  if (vtkCompositeDataSet::SafeDownCast(target) && !this->WrapBlocksTogether && !field)
  {
    return {}; // each block has sizes of its own
  }
  const bool givenStart = this->GetNumberOfInputConnections(2) > 0;
  const convert::PolygonMeshes meshes = convert::polygonMeshes(target);
  Box box = convert::surfaceBounds(meshes.meshes);
  WrapSettings chosen = this->CoreSettings();
  const convert::Geometry use = convert::chooseGeometry(this->InputGeometry, !box.empty());
  if (target && use.points && !field) // as StartSession
  {
    PointList points = wrappedPoints(target, meshes.meshes.empty() ? nullptr : meshes.meshes[0], use);
    if (checkPoints(points))
    {
      box = use.polygons ? box : Box();
      box.extend(Box::around(points));
      // The points go to the cloud (no copy): they are not needed here after it.
      const PointCloud& cloud = this->MeasuredCloud(target, points.size(), [&] { return measureCloud(std::move(points)); });
      chosen = withPointSizes(chosen, box, cloud, givenStart);
    }
    else if (!use.polygons) // no points: no field (StartSession says why); beside polygons: the polygons'
    {
      return {};
    }
  }
  const bool sized = !box.empty() && box.min.allFinite() && box.max.allFinite(); // as StartSession checks
  const WrapSettings settings = chosen.resolved(box);
  convert::WrapSizes sizes;
  if (sized)
  {
    sizes = { 0, settings.gapSize, settings.evolution.remeshing.targetLength }; // 0: Remeshing off
  }
  if (field)
  {
    sizes.cell = field->GetSpacing()[0];
    for (int port = 0; port < 2; ++port)
    {
      for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
      {
        vtkInformation* info = inputVector[port]->GetInformationObject(c);
        if (info->Get(vtkDataObject::DATA_OBJECT()) == field && info->Has(vtkDataObject::SPACING()))
        {
          sizes.cell = info->Get(vtkDataObject::SPACING())[0];
        }
      }
    }
  }
  else if (GridLattice lattice; sized && placeGrid(box, settings.fieldPlacement(box, givenStart), lattice))
  {
    sizes.cell = lattice.spacing.x();
  }
  return sizes;
}

int vtkShrinkWrapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The whole target, field and starting surface, whatever time is asked of the output.
  for (int port = 0; port < 3; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(c);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      info->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
  }
  return 1;
}

const PointCloud& vtkShrinkWrapFilter::MeasuredCloud(
  vtkDataObject* target, std::size_t points, const std::function<PointCloud()>& measure)
{
  if (const PointCloud* cached = this->CachedCloud(target); cached && this->Cloud.points == points)
  {
    return *cached;
  }
  CloudCache& c = this->Cloud;
  c = { target, target ? target->GetMTime() : 0, this->InputGeometry, points, std::make_unique<PointCloud>(measure()) };
  return *c.cloud;
}

const PointCloud* vtkShrinkWrapFilter::CachedCloud(vtkDataObject* target) const
{
  const CloudCache& c = this->Cloud;
  const bool current =
    target && c.cloud && c.target == target && c.key == target->GetMTime() && c.geometry == this->InputGeometry;
  return current ? c.cloud.get() : nullptr;
}

vtkMTimeType vtkShrinkWrapFilter::SessionKey()
{
  vtkMTimeType key = this->GetMTime();
  for (int port = 0; port < 3; ++port)
  {
    for (int c = 0; c < this->GetNumberOfInputConnections(port); ++c)
    {
      if (vtkDataObject* data = this->GetInputDataObject(port, c))
      {
        key = std::max(key, data->GetMTime());
      }
    }
  }
  return key;
}

// Port 0 may hold the target and its distance field together: ParaView connects both there when both
// are selected as Shrink Wrap is created. An image with a SignedDistance point array is then the field
// (unless port 1 has one); the rest is the target, one dataset.
bool vtkShrinkWrapFilter::TargetAndField(vtkInformationVector** inputVector, vtkDataObject*& target, vtkImageData*& field)
{
  std::vector<vtkDataObject*> port0;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    port0.push_back(vtkDataObject::GetData(inputVector[0], c));
  }
  const int targets = targetAndField(port0, vtkImageData::GetData(inputVector[1], 0), target, field);
  if (targets > 1)
  {
    vtkErrorMacro("Shrink Wrap wraps one target at a time, and its Input holds " << targets
                                                                                  << " (besides a distance field).");
    return false;
  }
  return true;
}

// Every rank takes part (the target is made whole on each); piece 0 wraps it, under MPI the other
// pieces are empty.
void vtkShrinkWrapFilter::ExecuteWhole(vtkInformationVector** inputVector, vtkInformation* outInfo, vtkPolyData* output)
{
  vtkDataObject* found = nullptr;
  vtkImageData* field = nullptr;
  const bool ok = this->TargetAndField(inputVector, found, field);
  vtkDataObject* whole = convert::wholeInput(ok ? found : nullptr, this->Controller, this->Gathered);
  if (ok && convert::pieceRequest(outInfo).piece == 0)
  {
    this->Execute(
      [&] {
        // A composite's blocks together as one target, appended only when a session starts (not at
        // every time asked for).
        const vtkSmartPointer<vtkDataSet> together =
          vtkCompositeDataSet::SafeDownCast(whole) ? convert::appendedLeaves(whole) : nullptr;
        return this->StartSession(
          together ? together.Get() : vtkDataSet::SafeDownCast(whole), field, vtkPolyData::GetData(inputVector[2], 0));
      },
      outInfo, output);
  }
}

bool vtkShrinkWrapFilter::StartSession(vtkDataSet* targetData, vtkImageData* field, vtkPolyData* initial)
{
  const convert::PolygonMeshes input = convert::polygonMeshes(targetData);
  vtkPolyData* target = input.meshes.empty() ? nullptr : input.meshes[0];
  const bool hasPolygons = target && target->GetNumberOfPolys() + target->GetNumberOfStrips() > 0;
  const convert::Geometry use = convert::chooseGeometry(this->InputGeometry, hasPolygons);
  if (use.polygons && !hasPolygons)
  {
    vtkErrorMacro("Cannot wrap: the target has no polygons or 3-D cells, and Input Geometry is Polygons; choose "
                  "Automatic or Points to wrap its points.");
    return false;
  }
  if (use.polygons && !input.extractedFrom.empty())
  {
    vtkOutputWindowDisplayText(("Shrink Wrap: the target (" + input.extractedFrom +
      ") is wrapped by its outer surface, as Extract Surface gives it.\n").c_str());
  }
  if (const Status valid = this->CoreSettings().validate(); !valid)
  {
    vtkErrorMacro(<< valid.message() << ".");
    return false;
  }
  // The points wrapped, if any: all the target's, or those beside its polygons (issue #13); those of
  // the cloud RequestInformation measured, if it did.
  PointList converted;
  const PointCloud* cached = use.points ? this->CachedCloud(targetData) : nullptr;
  const PointList& points = cached ? cached->points->points() : converted;
  if (use.points && !cached)
  {
    converted = wrappedPoints(targetData, target, use);
  }
  if (use.points)
  {
    if (use.polygons && points.empty())
    {
      vtkWarningMacro("Input Geometry is Polygons and Points, but every point of the target lies on its polygons: "
                      "the polygons are wrapped.");
    }
    else
    {
      Status ok = checkPoints(points);
      if (ok && !use.polygons)
      {
        ok = checkPointsEnclose(points);
      }
      if (!ok)
      {
        vtkErrorMacro("Cannot wrap: " << ok.message() << ".");
        return false;
      }
      if (field)
      {
        vtkErrorMacro("Cannot wrap points on a Distance Field: disconnect it (the wrap computes the points' own).");
        return false;
      }
    }
  }
  const bool wrapsPoints = !points.empty();
  Box targetBox = use.polygons ? convert::boundsOf(target) : Box();
  targetBox.extend(Box::around(points));
  if (!targetBox.min.allFinite() || !targetBox.max.allFinite())
  {
    vtkErrorMacro("The target has NaN or infinite coordinates.");
    return false;
  }
  const PointCloud cloud =
    wrapsPoints ? this->MeasuredCloud(targetData, points.size(), [&] { return measureCloud(points); }) : PointCloud();
  const WrapSettings settings = (wrapsPoints ? withPointSizes(this->CoreSettings(), targetBox, cloud, initial != nullptr)
                                             : this->CoreSettings())
                                  .resolved(targetBox);
  if (const Status fits = settings.fits(targetBox); !fits)
  {
    vtkErrorMacro(<< fits.message() << ".");
    return false;
  }
  WrapFields fields;
  if (!wrapsPoints && !this->FieldsOf(target, field, initial != nullptr, settings, fields))
  {
    return false;
  }
  if (wrapsPoints)
  {
    std::shared_ptr<const TriangleSource> polygons;
    if (use.polygons)
    {
      convert::SoupCounts counts;
      const TriangleSoup soup = convert::soupOf({ target }, counts);
      if (const Status valid = counts.badCells > 0 ? Status::failure("the target has cells whose point ids are out of range")
                                                   : checkSoup(soup);
          !valid)
      {
        vtkErrorMacro("Cannot wrap: " << valid.message() << ".");
        return false;
      }
      polygons = std::make_shared<const TriangleSource>(soup);
    }
    if (const Status made =
          pointFields(cloud, polygons, initial != nullptr, settings, fields);
        !made)
    {
      vtkErrorMacro("Cannot wrap: " << made.message() << ".");
      return false;
    }
    vtkOutputWindowDisplayText(("Shrink Wrap: " + std::string(use.polygons ? "the target's polygons and the " : "the target's ") +
      std::to_string(points.size()) + (use.polygons ? " points beside them" : " points") + " are wrapped" +
      (this->InputGeometry == AUTOMATIC ? " (it has no polygons)" : "") + ".\n").c_str());
  }
  TriangleSurface given;
  if (initial && !convert::surfaceOf(initial, given))
  {
    vtkErrorMacro("The InitialSurface must be made of triangles only, with finite points and valid point ids.");
    return false;
  }
  SurfaceMesh start;
  int specks = 0;
  // The start's contour without the case table's joins where they add handles the field has not (the
  // hand's mesh and its 200,000 points lose one, the dragon's mesh keeps only its true one; RESULTS.md,
  // 2026-11-27).
  const Contour contour = [](const DistanceGrid& grid, double value) { return convert::contour(grid, value, true); };
  Status status = startingSurface(fields.driving.grid(), targetBox, initial ? &given : nullptr, settings.start,
    settings.evolution.flips, contour, start, specks);
  if (specks > 0)
  {
    vtkWarningMacro("Left out " << specks << " piece(s) of the starting surface smaller than two cells "
                                "of the distance field.");
  }
  if (status)
  {
    status = WrapSession::create(std::move(fields), targetBox, start, settings, this->Current);
  }
  if (!status)
  {
    vtkErrorMacro("Cannot wrap: " << status.message() << ".");
  }
  return status.ok();
}

// The DistanceField input, or the target's field computed here with Mesh Signed Distance's algorithm;
// closed over the gaps the wrap bridges, and exact near the target (WrapFields).
bool vtkShrinkWrapFilter::FieldsOf(
  vtkPolyData* target, vtkImageData* image, bool givenStart, const WrapSettings& settings, WrapFields& fields)
{
  convert::SoupCounts counts;
  const TriangleSoup soup = convert::soupOf({ target }, counts);
  if (counts.badCells > 0)
  {
    vtkErrorMacro("Cannot wrap: the target has cells whose point ids are out of range.");
    return false;
  }
  DistanceGrid grid;
  std::shared_ptr<const TriangleSource> exact;
  bool isSigned = true;
  if (image)
  {
    const Status read = convert::gridOf(image, "SignedDistance", grid);
    if (!read)
    {
      vtkErrorMacro("Cannot wrap: " << read.message() << ".");
      return false;
    }
    isSigned = std::any_of(grid.values().begin(), grid.values().end(), [](float d) { return d < 0; });
    if (std::all_of(grid.values().begin(), grid.values().end(), [](float d) { return d < 0; }))
    {
      vtkErrorMacro("Cannot wrap: the DistanceField has no outside (every value is negative), so no surface "
                    "can start around the target.");
      return false;
    }
    if (!isSigned)
    {
      vtkWarningMacro("The DistanceField has no inside (no negative value): it is taken as unsigned, and the wrap "
                      "stops at the distance it reaches from outside and inside alike.");
    }
    if (settings.exactNearTarget && checkSoup(soup))
    {
      exact = std::make_shared<const TriangleSource>(soup);
    }
  }
  else
  {
    const GridPlacement placement = settings.fieldPlacement(convert::surfaceBounds({ target }), givenStart);
    SignedDistanceResult result;
    SignedDistanceSettings distance;
    distance.windingNumber = settings.closeHoles;
    const Status status = signedDistanceGrid(
      soup, convert::surfaceBounds({ target }), placement, distance, grid, result, {}, &exact);
    if (!status)
    {
      vtkErrorMacro("Cannot wrap: the target's distance field: " << status.message() << ".");
      return false;
    }
    isSigned = result.isSigned;
    if (shrinkwrap::signNeedsWarning(result, true))
    {
      vtkWarningMacro("The target's distance field is "
        << shrinkwrap::signStatus(result, true)
        << (result.isSigned ? "." : ": the wrap stops at the distance it reaches from outside and inside alike."));
    }
  }
  const Status status = wrapFields(std::move(grid), isSigned, exact, settings, fields);
  if (!status)
  {
    vtkErrorMacro("Cannot wrap: " << status.message() << ".");
  }
  return status.ok();
}

int vtkShrinkWrapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
  output->Initialize();
  vtkCompositeDataSet* blocks = this->WrapBlocksTogether ? nullptr : compositeTarget(inputVector[0]);
  this->SetProgressShiftScale(0, 1); // (a run that threw may have left a block's share)
  try // memory can run out below any estimate (a process limit, a job's cap)
  {
    if (blocks)
    {
      this->ExecuteBlocks(blocks, inputVector, outInfo, vtkCompositeDataSet::SafeDownCast(output));
    }
    else
    {
      this->ExecuteWhole(inputVector, outInfo, vtkPolyData::SafeDownCast(output));
    }
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    this->Current.reset(); // a half-made step is not kept; the next update starts over
    this->Blocks.clear();
    vtkErrorMacro("Out of memory: lower Subdivision Level, Resolution or Cache Memory Limit.");
  }
  catch (const std::exception& e) // e.g. threads that cannot start under the same limits
  {
    output->Initialize();
    this->Current.reset();
    this->Blocks.clear();
    vtkErrorMacro("Shrink Wrap failed: " << e.what() << ".");
  }
  return 1;
}

// Each block of a composite target is wrapped on its own, with a session (and a cache) of its own;
// under MPI the blocks are shared out among the pieces by their expected cost (piecesOfBlocks; the
// other pieces leave a block empty), so the ranks wrap them in parallel.
void vtkShrinkWrapFilter::ExecuteBlocks(
  vtkCompositeDataSet* blocks, vtkInformationVector** inputVector, vtkInformation* outInfo, vtkCompositeDataSet* output)
{
  output->CopyStructure(blocks);
  if (this->GetNumberOfInputConnections(1) > 0 || this->GetNumberOfInputConnections(2) > 0 ||
    inputVector[0]->GetNumberOfInformationObjects() > 1)
  {
    vtkErrorMacro("A composite target is wrapped block by block, each on a distance field and a start of its own: "
                  "disconnect the Distance Field and the Initial Surface.");
    return;
  }
  const convert::PieceRequest request = convert::pieceRequest(outInfo);
  const int piece = request.piece;
  const vtkMTimeType key = this->SessionKey();
  if (key != this->BlocksKey)
  {
    this->Blocks.clear(); // another target or other properties: every block starts over
    this->BlocksKey = key;
    this->BlockPieces.clear();
  }
  vtkSmartPointer<vtkCompositeDataIterator> block = vtkSmartPointer<vtkCompositeDataIterator>::Take(blocks->NewIterator());
  std::vector<vtkDataSet*> targets;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    targets.push_back(vtkDataSet::SafeDownCast(block->GetCurrentDataObject()));
  }
  // Shared out once per target and properties, not at every time asked for.
  const std::vector<int> wrappedOn = convert::piecesOfLeaves(blocks, targets, request, this->Controller, [&] {
    if (this->BlockPieces.size() != targets.size() || this->BlockPiecesOf != request.pieces)
    {
      this->BlockPieces = request.pieces > 1 ? piecesOfBlocks(targets, request.pieces, this->CoreSettings())
                                             : std::vector<int>(targets.size(), 0);
      this->BlockPiecesOf = request.pieces;
    }
    return this->BlockPieces;
  });
  const auto here = static_cast<double>(std::count(wrappedOn.begin(), wrappedOn.end(), piece));
  int count = 0, done = 0;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem(), ++count)
  {
    vtkNew<vtkPolyData> wrap;
    vtkDataSet* target = targets[count];
    if (target && wrappedOn[count] == piece)
    {
      this->SetProgressShiftScale(done++ / here, 1 / here); // one progress bar over the blocks
      // The block's session in place of the single target's while it runs.
      BlockSession& own = this->Blocks[block->GetCurrentFlatIndex()];
      std::swap(own.session, this->Current);
      std::swap(own.key, this->CurrentKey);
      std::swap(own.seconds, this->ComputeSeconds);
      this->Execute([&] { return this->StartSession(target, nullptr, nullptr); }, outInfo, wrap);
      std::swap(own.session, this->Current);
      std::swap(own.key, this->CurrentKey);
      std::swap(own.seconds, this->ComputeSeconds);
    }
    output->SetDataSet(block, wrap);
  }
  this->SetProgressShiftScale(0, 1);
  this->ShowSizes({}); // each block had sizes of its own
}

void vtkShrinkWrapFilter::Execute(const std::function<bool()>& start, vtkInformation* outInfo, vtkPolyData* output)
{
  // Any change of an input or a property starts a new session (and drops the cache).
  const vtkMTimeType key = this->SessionKey();
  if (!this->Current || this->CurrentKey != key)
  {
    this->Current.reset();
    bool started = false;
    const auto begin = std::chrono::steady_clock::now();
    onAllCores([&] { started = start(); });
    this->ComputeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (!started) // a session is kept only when it started
    {
      return;
    }
    this->CurrentKey = key;
  }
  const int wanted = this->StepAsked(outInfo);
  const int computed = this->Current->computedSteps();
  const auto begin = std::chrono::steady_clock::now();
  const bool advanced = this->Advance(wanted);
  this->ComputeSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  if (advanced)
  {
    // The end of a run: the last step, computed now.
    this->WriteOutput(wanted, wanted == this->NumberOfSteps && this->Current->computedSteps() > computed, output);
  }
  // The pipeline takes an execution as up to date even when a property changed while it ran (a panel
  // edit, a script's callback): RunAgain makes the next request run again, with the new values.
  if (this->SessionKey() != key)
  {
    this->RunAgain = true;
    vtkWarningMacro("Properties or inputs changed during the run; they apply from the next update.");
  }
}

// The requested time snapped to a step (clamped to the steps there are, before rounding: a time far
// past the end is the last step), else the last step; NaN asks for no time.
int vtkShrinkWrapFilter::StepAsked(vtkInformation* outInfo) const
{
  const int last = this->NumberOfSteps;
  const double asked = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) / this->TimeStep
    : std::nan("");
  if (std::isnan(asked))
  {
    return last;
  }
  return asked <= 0 ? 0 : (asked >= last ? last : static_cast<int>(std::lround(asked)));
}

// Computes the missing steps up to `step`; false when the run was aborted.
bool vtkShrinkWrapFilter::Advance(int step)
{
  if (this->NumberOfSteps == 0)
  {
    vtkWarningMacro("NumberOfSteps is 0: showing the starting surface.");
  }
  const int computed = this->Current->computedSteps();
  const shrinkwrap::Progress progress([this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  });
  bool finished = false;
  onAllCores([&] { finished = this->Current->advanceTo(step, progress); });
  // An abort ends this run: the empty output stands until a property, an input or the time asked
  // for changes (then the run resumes from the cache, or starts over).
  if (!finished)
  {
    this->AbortExecute = 0; // honoured; a set flag would stop every later run at its first step
    vtkWarningMacro("Shrink Wrap was aborted; the output is empty (computed steps stay cached).");
    return false;
  }
  if (this->Current->lastGood() >= 0 && this->Current->computedSteps() > computed)
  {
    vtkWarningMacro("The evolution failed: " << this->Current->failure() << "; later times show step "
                                             << this->Current->lastGood() << ".");
  }
  return true;
}

void vtkShrinkWrapFilter::WriteOutput(int wanted, bool finished, vtkPolyData* output)
{
  const WrapSession& s = *this->Current;
  const WrapSession::Surface surface = s.surface(wanted);
  SurfaceMesh mesh;
  if (const Status closed = SurfaceMesh::build(surface.points, *surface.cached->triangles, mesh); !closed)
  {
    vtkErrorMacro("Internal error: step " << surface.step << " is not a closed surface: " << closed.message() << ".");
    return;
  }
  convert::writeSurface(surface.points, mesh, s.fields().target, surface.cached->tangentialVelocity, output);
  // The wrap must not pass through itself; if it does at this step, the cells say where.
  const SelfIntersections crossings = findSelfIntersections(surface.points, mesh.triangles());
  convert::addSelfIntersections(crossings, output);
  std::string status = "ok";
  if (s.lastGood() >= 0 && wanted > s.lastGood())
  {
    status = "failed: " + s.failure();
  }
  else if (crossings.pairs > 0)
  {
    status = "self-intersecting: " + std::to_string(crossings.pairs) + " triangle pairs cross";
    vtkWarningMacro("The surface of step " << surface.step << " passes through itself (" << crossings.pairs
                                           << " triangle pairs cross; cell array SelfIntersecting).");
  }
  convert::addStepFields(surface.step, surface.step * this->TimeStep, status, output);
  this->ShowSizes({ s.fields().driving.grid().lattice().spacing.x(), s.settings().gapSize,
    s.settings().evolution.remeshing.targetLength });
  const convert::WrapSummary summary = convert::summarize(
    output, { this->FieldCellSize, this->ChosenGapSize, this->ChosenTargetEdgeLength }, surface.step, this->ComputeSeconds);
  convert::addSummary(summary, output);
  if (finished)
  {
    vtkOutputWindowDisplayText(("Shrink Wrap: " + summary.text() + ".\n").c_str());
  }
}

void vtkShrinkWrapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputGeometry: " << convert::geometryName(this->InputGeometry) << "\n";
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "NumberOfSteps: " << this->NumberOfSteps << "\n";
  os << indent << "SubdivisionLevel: " << this->SubdivisionLevel << "\n";
  os << indent << "C1: " << this->C1 << "\n";
  os << indent << "C2: " << this->C2 << "\n";
  os << indent << "C: " << this->C << "\n";
  os << indent << "D: " << this->D << "\n";
  os << indent << "TangentialRedistribution: " << this->TangentialRedistribution << "\n";
  os << indent << "OmegaAngle: " << this->OmegaAngle << "\n";
  os << indent << "OmegaVolume: " << this->OmegaVolume << "\n";
  os << indent << "RhoA: " << this->RhoA << "\n";
  os << indent << "DistanceWeighting: " << this->DistanceWeighting << "\n";
  os << indent << "EdgeFlips: " << this->EdgeFlips << "\n";
  os << indent << "EdgeCollapses: " << this->EdgeCollapses << "\n";
  os << indent << "CoverRims: " << this->CoverRims << "\n";
  os << indent << "FitFacets: " << this->FitFacets << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << (this->CreaseAngle < 180 ? "\n" : " (rims only)\n");
  os << indent << "FlipDihedralLimit: " << this->FlipDihedralLimit << "\n";
  os << indent << "StartingShape: " << (this->StartingShape == ICOSPHERE ? "Icosphere" : "Offset Surface") << "\n";
  os << indent << "StartOffset: " << this->StartOffset << "\n";
  os << indent << "GapSize: " << this->GapSize << (this->GapSize > 0 ? "\n" : " (automatic)\n");
  os << indent << "CloseHoles: " << this->CloseHoles << "\n";
  os << indent << "Remeshing: " << this->Remeshing << "\n";
  os << indent << "TargetEdgeLength: " << this->TargetEdgeLength << (this->TargetEdgeLength > 0 ? "\n" : " (automatic)\n");
  os << indent << "EdgeLengthRange: " << this->EdgeLengthRange[0] << " " << this->EdgeLengthRange[1]
     << (this->EdgeLengthRange[0] < 1 || this->EdgeLengthRange[1] > 1 ? " (adaptive)\n" : " (uniform)\n");
  os << indent << "InitialRelaxation: " << this->InitialRelaxation << "\n";
  os << indent << "AutomaticScaling: " << this->AutomaticScaling << "\n";
  os << indent << "SolverTolerance: " << this->SolverTolerance << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "CacheMemoryLimit: " << this->CacheMemoryLimit << " MiB\n";
  os << indent << "WrapBlocksTogether: " << this->WrapBlocksTogether << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "FieldCellSize: " << this->FieldCellSize << "\n";
  os << indent << "ChosenGapSize: " << this->ChosenGapSize << "\n";
  os << indent << "ChosenTargetEdgeLength: " << this->ChosenTargetEdgeLength << "\n";
}
