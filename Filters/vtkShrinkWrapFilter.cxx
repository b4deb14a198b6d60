#include "vtkShrinkWrapFilter.h"

#include "RankInputs.h"
#include "TargetInput.h"
#include "VTKConversions.h"
#include "vtkInputGeometry.h"

#include "Common/Parallel.h"
#include "Surface/SelfIntersections.h"
#include "Wrap/AutomaticSizes.h"
#include "Wrap/Wrap.h"

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
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShrinkWrapFilter);
vtkCxxSetObjectMacro(vtkShrinkWrapFilter, Controller, vtkMultiProcessController);

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

double secondsSince(std::chrono::steady_clock::time_point begin)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// The data objects on a port, by connection.
std::vector<vtkDataObject*> dataOf(vtkInformationVector* port)
{
  std::vector<vtkDataObject*> data;
  for (int c = 0; c < port->GetNumberOfInformationObjects(); ++c)
  {
    data.push_back(port->GetInformationObject(c)->Get(vtkDataObject::DATA_OBJECT()));
  }
  return data;
}

// The piece that wraps each block (convert::shareOut), by the wrap's expected vertex count: the
// block's area over L^2 (L as with Remeshing); 1 for a block without polygons (points: no area).
std::vector<int> piecesOfBlocks(
  const std::vector<vtkDataSet*>& targets, int pieces, WrapSettings settings)
{
  settings.remeshing = true;
  std::vector<double> cost(targets.size(), 1.0);
  for (std::size_t b = 0; b < targets.size(); ++b)
  {
    convert::SoupCounts counts;
    const TriangleSoup soup = convert::soupOf(convert::polygonMeshes(targets[b]).meshes, counts);
    const Box box = convert::boundsOf(targets[b]);
    const double length = box.empty() ? 0.0 : edgeLengthFor(settings, box).value_or(0);
    const double vertices = soup.area() / (length * length);
    cost[b] = length > 0 && std::isfinite(vertices) ? std::max(1.0, vertices) : 1.0;
  }
  return convert::shareOut(cost, pieces);
}

// The target as the core takes it, kept while the data and the Input Geometry stay.
struct ConvertedTarget
{
  const vtkDataObject* data = nullptr;
  vtkMTimeType key = 0; // the data's
  int geometry = 0;     // InputGeometry
  Status status;
  WrapTarget target;
  Notes notes;
};

// The plan for the inputs and properties as they were.
struct PlannedWrap
{
  vtkMTimeType key = 0; // SessionKey
  const vtkDataObject* data = nullptr;
  std::optional<GridLattice> field;
  bool givenStart = false;
  Status status;
  WrapPlan plan;
};

struct Session
{
  std::unique_ptr<WrapSession> session;
  vtkMTimeType key = 0;
  double seconds = 0; // fields, start and steps
};
} // namespace

struct vtkShrinkWrapFilter::vtkInternals
{
  ConvertedTarget Converted;
  PlannedWrap Planned;
  // Everything derived from the inputs and properties, dropped when either changes: the current
  // session, and a composite target's blocks' sessions (by flat index), swapped in while each runs.
  std::unique_ptr<WrapSession> Current;
  vtkMTimeType CurrentKey = 0;
  double ComputeSeconds = 0;
  std::map<unsigned int, Session> Blocks;
  vtkMTimeType BlocksKey = 0;
  std::vector<int> BlockPieces; // the piece that wraps each block of a composite every rank holds
  int BlockPiecesOf = 0;        // among so many pieces
  std::unique_ptr<convert::GatheredInput> Gathered; // a distributed target as gathered here

  // The target as the core takes it, converted once while the data and Input Geometry stay (both
  // passes need it; measuring a cloud takes a while). A composite is wrapped as its blocks appended.
  const ConvertedTarget& TargetOf(vtkDataObject* data, int geometry);
  void Swap(Session& block);
};

vtkShrinkWrapFilter::vtkShrinkWrapFilter()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(1);
  this->SetProperties(WrapSettings());
  this->SetProgressText("Shrink Wrap");
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkShrinkWrapFilter::~vtkShrinkWrapFilter()
{
  this->SetController(nullptr);
}

// The properties from the core's settings (the defaults are stated there once), and back.
void vtkShrinkWrapFilter::SetProperties(const WrapSettings& s)
{
  const EvolverSettings& e = s.evolution;
  this->TimeStep = e.timeStep;
  this->NumberOfSteps = s.steps;
  this->SubdivisionLevel = s.start.subdivision;
  this->C1 = e.C1;
  this->C2 = e.C2;
  this->C = e.C;
  this->D = e.D;
  this->TangentialRedistribution = static_cast<int>(e.redistribution); // NONE, ANGLE, VOLUME
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
  this->StartingShape = static_cast<int>(s.start.shape); // ICOSPHERE, OFFSET_SURFACE
  this->StartOffset = s.start.offset;
  this->GapSize = s.gapSize.value_or(0);
  this->CloseHoles = s.closeHoles;
  this->Remeshing = s.remeshing;
  this->TargetEdgeLength = s.targetEdgeLength.value_or(0);
  this->EdgeLengthRange[0] = s.edgeLengthRange[0];
  this->EdgeLengthRange[1] = s.edgeLengthRange[1];
  this->InitialRelaxation = s.start.relaxation;
  this->AutomaticScaling = s.automaticScaling;
  this->SolverTolerance = e.solverTolerance;
  this->Resolution = s.resolution;
  this->CacheMemoryLimit = s.cacheMiB;
}

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
  // 0 asks for the automatic size; anything else (a negative value too) is the user's to check.
  s.gapSize = this->GapSize != 0 ? std::optional<double>(this->GapSize) : std::nullopt;
  s.closeHoles = this->CloseHoles;
  s.remeshing = this->Remeshing;
  s.targetEdgeLength =
    this->TargetEdgeLength != 0 ? std::optional<double>(this->TargetEdgeLength) : std::nullopt;
  s.edgeLengthRange = { this->EdgeLengthRange[0], this->EdgeLengthRange[1] };
  s.start.relaxation = this->InitialRelaxation;
  s.automaticScaling = this->AutomaticScaling;
  e.solverTolerance = this->SolverTolerance;
  s.resolution = this->Resolution;
  s.cacheMiB = this->CacheMemoryLimit;
  return s;
}

int vtkShrinkWrapFilter::GetNumberOfComputedSteps() const
{
  int steps = this->Internals->Current ? this->Internals->Current->computedSteps() : 0;
  for (const auto& block : this->Internals->Blocks)
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
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1); // the target, and maybe its field
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
int vtkShrinkWrapFilter::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkCompositeDataSet* composite =
    this->WrapBlocksTogether ? nullptr : compositeTarget(inputVector[0]);
  convert::makeOutput<vtkPolyData>(outputVector->GetInformationObject(0), composite);
  return 1;
}

int vtkShrinkWrapFilter::ComputePipelineMTime(vtkInformation* request,
  vtkInformationVector** inInfoVec, vtkInformationVector* outInfoVec, int requestFromOutputPort,
  vtkMTimeType* mtime)
{
  const int result = this->Superclass::ComputePipelineMTime(
    request, inInfoVec, outInfoVec, requestFromOutputPort, mtime);
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
  // ParaView reads information properties after RequestInformation, not after RequestData: the
  // panel's sizes are planned here from the inputs as they stand (0 while the target has not been
  // computed, and for a composite wrapped block by block); RequestData then shows the run's.
  this->ShowSizes({});
  onAllCores([&] {
    vtkDataObject* target = nullptr;
    vtkImageData* field = nullptr;
    const auto port1 = dataOf(inputVector[1]);
    const bool one = this->Inputs(
      dataOf(inputVector[0]), port1.empty() ? nullptr : port1[0], target, field, false);
    const bool blockByBlock = vtkCompositeDataSet::SafeDownCast(target) && !this->WrapBlocksTogether;
    if (one && target && !blockByBlock)
    {
      this->Plan(target, this->FieldLattice(inputVector, field), this->HasInitialSurface());
    }
  });
  return 1;
}

// The lattice of a connected field as its pipeline information gives it (RequestInformation comes
// before the field is computed), else as it stands.
std::optional<GridLattice> vtkShrinkWrapFilter::FieldLattice(
  vtkInformationVector** inputVector, vtkImageData* field)
{
  if (!field)
  {
    return std::nullopt;
  }
  GridLattice lattice = convert::latticeOf(field);
  for (int port = 0; port < 2; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(c);
      if (info->Get(vtkDataObject::DATA_OBJECT()) == field && info->Has(vtkDataObject::SPACING()))
      {
        const double* spacing = info->Get(vtkDataObject::SPACING());
        lattice.spacing = Vec3(spacing[0], spacing[1], spacing[2]);
      }
    }
  }
  return lattice;
}

void vtkShrinkWrapFilter::ShowSizes(const WrapSizes& sizes)
{
  this->FieldCellSize = sizes.cell;
  this->ChosenGapSize = sizes.gap;
  this->ChosenTargetEdgeLength = sizes.edgeLength.value_or(0); // 0: Remeshing off
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

// Port 0 may hold the target and its distance field together: ParaView connects both there when
// both are selected as Shrink Wrap is created. An image with a SignedDistance point array is then
// the field (unless port 1 has one); the rest is the target, one dataset. False, and an error if
// `complain`, when port 0 holds more than one target.
bool vtkShrinkWrapFilter::Inputs(const std::vector<vtkDataObject*>& port0, vtkDataObject* port1,
  vtkDataObject*& target, vtkImageData*& field, bool complain)
{
  field = vtkImageData::SafeDownCast(port1);
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
  if (targets > 1 && complain)
  {
    vtkErrorMacro("Shrink Wrap wraps one target at a time, and its Input holds "
      << targets << " (besides a distance field).");
  }
  return targets <= 1;
}

const ConvertedTarget& vtkShrinkWrapFilter::vtkInternals::TargetOf(vtkDataObject* data, int geometry)
{
  ConvertedTarget& c = this->Converted;
  if (c.data == data && c.key == data->GetMTime() && c.geometry == geometry)
  {
    return c;
  }
  c = ConvertedTarget{ data, data->GetMTime(), geometry };
  vtkSmartPointer<vtkDataObject> whole = data;
  if (vtkCompositeDataSet::SafeDownCast(data))
  {
    whole = convert::appendedLeaves(data);
  }
  convert::TargetParts parts;
  c.status = convert::readTarget(whole, geometry, { "target", "wrapped" }, parts, c.notes);
  const std::size_t points = parts.points.size();
  if (c.status)
  {
    c.status = makeTarget(std::move(parts.polygons), std::move(parts.points), c.target);
  }
  if (c.status && points > 0)
  {
    inform(c.notes,
      std::string(parts.use.polygons ? "the target's polygons and the " : "the target's ") +
        std::to_string(points) + (parts.use.polygons ? " points beside them" : " points") +
        " are wrapped" +
        (geometry == vtkInputGeometry::AUTOMATIC ? " (it has no polygons)" : ""));
  }
  return c;
}

// The plan for a target as it is, with a field of this lattice (if any) and maybe a given start:
// made once while the inputs and properties stay. Null when none can be made (`Planned.status`
// says why); shows its sizes in the panel.
const WrapPlan* vtkShrinkWrapFilter::Plan(
  vtkDataObject* data, const std::optional<GridLattice>& field, bool givenStart)
{
  PlannedWrap& p = this->Internals->Planned;
  const vtkMTimeType key = this->SessionKey();
  const bool same = p.key == key && p.data == data && p.givenStart == givenStart &&
    p.field.has_value() == field.has_value() && (!field || *p.field == *field);
  if (!same)
  {
    const ConvertedTarget& converted = this->Internals->TargetOf(data, this->InputGeometry);
    p = PlannedWrap{ key, data, field, givenStart, converted.status };
    WrapTarget target = converted.target;
    target.fieldLattice = field;
    target.givenStart = givenStart;
    if (p.status)
    {
      p.status = planWrap(target, this->CoreSettings(), p.plan);
    }
  }
  if (p.status)
  {
    this->ShowSizes(p.plan.sizes());
  }
  return p.status ? &p.plan : nullptr;
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
  catch (const std::exception& e) // std::bad_alloc, threads that cannot start under the same limits
  {
    output->Initialize();
    this->Internals->Current.reset(); // a half-made step is not kept; the next update starts over
    this->Internals->Blocks.clear();
    if (dynamic_cast<const std::bad_alloc*>(&e))
    {
      vtkErrorMacro("Out of memory: lower Subdivision Level, Resolution or Cache Memory Limit.");
    }
    else
    {
      vtkErrorMacro("Shrink Wrap failed: " << e.what() << ".");
    }
  }
  return 1;
}

// Each block of a composite target is wrapped on its own, with a session (and a cache) of its own;
// under MPI the blocks are shared out among the pieces by their expected cost (piecesOfBlocks; the
// other pieces leave a block empty), so the ranks wrap them in parallel.
void vtkShrinkWrapFilter::ExecuteBlocks(vtkCompositeDataSet* blocks,
  vtkInformationVector** inputVector, vtkInformation* outInfo, vtkCompositeDataSet* output)
{
  output->CopyStructure(blocks);
  if (this->GetNumberOfInputConnections(1) > 0 || this->GetNumberOfInputConnections(2) > 0 ||
    inputVector[0]->GetNumberOfInformationObjects() > 1)
  {
    vtkErrorMacro("A composite target is wrapped block by block, each on a distance field and a "
                  "start of its own: disconnect the Distance Field and the Initial Surface.");
    return;
  }
  const convert::PieceRequest request = convert::pieceRequest(outInfo);
  if (this->SessionKey() != this->Internals->BlocksKey)
  {
    this->Internals->Blocks.clear(); // another target or other properties: every block starts over
    this->Internals->BlocksKey = this->SessionKey();
    this->Internals->BlockPieces.clear();
  }
  auto block = vtkSmartPointer<vtkCompositeDataIterator>::Take(blocks->NewIterator());
  std::vector<vtkDataSet*> targets;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    targets.push_back(vtkDataSet::SafeDownCast(block->GetCurrentDataObject()));
  }
  // Shared out once per target and properties, not at every time asked for.
  const std::vector<int> wrappedOn =
    convert::piecesOfLeaves(blocks, targets, request, this->Controller, [&] {
      if (this->Internals->BlockPieces.size() != targets.size() || this->Internals->BlockPiecesOf != request.pieces)
      {
        this->Internals->BlockPieces = request.pieces > 1
          ? piecesOfBlocks(targets, request.pieces, this->CoreSettings())
          : std::vector<int>(targets.size(), 0);
        this->Internals->BlockPiecesOf = request.pieces;
      }
      return this->Internals->BlockPieces;
    });
  const auto here =
    static_cast<double>(std::count(wrappedOn.begin(), wrappedOn.end(), request.piece));
  int count = 0, done = 0;
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem(), ++count)
  {
    vtkNew<vtkPolyData> wrap;
    if (vtkDataSet* target = targets[count]; target && wrappedOn[count] == request.piece)
    {
      this->SetProgressShiftScale(done++ / here, 1 / here); // one progress bar over the blocks
      // The block's session in place of the single target's while it runs.
      Session& own = this->Internals->Blocks[block->GetCurrentFlatIndex()];
      this->Internals->Swap(own);
      this->Execute([&] { return this->StartSession(target, nullptr, nullptr); }, outInfo, wrap);
      this->Internals->Swap(own);
    }
    output->SetDataSet(block, wrap);
  }
  this->SetProgressShiftScale(0, 1);
  this->ShowSizes({}); // each block had sizes of its own
}

void vtkShrinkWrapFilter::vtkInternals::Swap(Session& block)
{
  std::swap(block.session, this->Current);
  std::swap(block.key, this->CurrentKey);
  std::swap(block.seconds, this->ComputeSeconds);
}

// Every rank takes part (the target is made whole on each); piece 0 wraps it, under MPI the other
// pieces are empty.
void vtkShrinkWrapFilter::ExecuteWhole(
  vtkInformationVector** inputVector, vtkInformation* outInfo, vtkPolyData* output)
{
  vtkDataObject* found = nullptr;
  vtkImageData* field = nullptr;
  const bool one = this->Inputs(
    dataOf(inputVector[0]), vtkImageData::GetData(inputVector[1], 0), found, field, true);
  vtkDataObject* whole = convert::wholeInput(one ? found : nullptr, this->Controller, this->Internals->Gathered);
  if (one && convert::pieceRequest(outInfo).piece == 0)
  {
    this->Execute(
      [&] { return this->StartSession(whole, field, vtkPolyData::GetData(inputVector[2], 0)); },
      outInfo, output);
  }
}

// The target's plan and its fields, start and session (Wrap.h).
bool vtkShrinkWrapFilter::StartSession(vtkDataObject* data, vtkImageData* image, vtkPolyData* initial)
{
  if (!data)
  {
    vtkErrorMacro("Cannot wrap: there is no target.");
    return false;
  }
  WrapTarget target = this->Internals->TargetOf(data, this->InputGeometry).target;
  std::optional<GridLattice> lattice;
  if (image)
  {
    DistanceGrid grid;
    if (const Status read = convert::gridOf(image, "SignedDistance", grid); !read)
    {
      vtkErrorMacro("Cannot wrap: " << read.message() << ".");
      return false;
    }
    lattice = grid.lattice();
    target.field = std::make_shared<const DistanceGrid>(std::move(grid));
  }
  if (initial)
  {
    TriangleSoup given;
    if (!convert::surfaceOf(initial, given))
    {
      vtkErrorMacro("The Initial Surface must be made of triangles only, with finite points and "
                    "valid point ids.");
      return false;
    }
    target.start = std::make_shared<const TriangleSoup>(std::move(given));
  }
  const WrapPlan* plan = this->Plan(data, lattice, initial != nullptr);
  this->Report(this->Internals->Converted.notes);
  if (!plan)
  {
    vtkErrorMacro("Cannot wrap: " << this->Internals->Planned.status.message() << ".");
    return false;
  }
  target.fieldLattice = lattice;
  target.givenStart = initial != nullptr;
  Notes notes;
  const Status status =
    startWrap(target, *plan, convert::contour, shrinkwrap::Progress(), notes, this->Internals->Current);
  this->Report(notes);
  if (!status)
  {
    vtkErrorMacro("Cannot wrap: " << status.message() << ".");
  }
  return status.ok();
}

void vtkShrinkWrapFilter::Report(const Notes& notes)
{
  for (const Note& note : notes)
  {
    if (note.kind == Note::Warning)
    {
      vtkWarningMacro(<< note.text << ".");
    }
    else
    {
      vtkOutputWindowDisplayText(("Shrink Wrap: " + note.text + ".\n").c_str());
    }
  }
}

shrinkwrap::Progress vtkShrinkWrapFilter::ProgressOf(double begin, double end)
{
  return shrinkwrap::Progress(
    [this](double fraction) {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    },
    begin, end);
}

void vtkShrinkWrapFilter::Execute(
  const std::function<bool()>& start, vtkInformation* outInfo, vtkPolyData* output)
{
  // Any change of an input or a property starts a new session (and drops the cache).
  const vtkMTimeType key = this->SessionKey();
  if (!this->Internals->Current || this->Internals->CurrentKey != key)
  {
    this->Internals->Current.reset();
    bool started = false;
    const auto begin = std::chrono::steady_clock::now();
    onAllCores([&] { started = start(); });
    this->Internals->ComputeSeconds = secondsSince(begin);
    if (!started) // a session is kept only when it started
    {
      return;
    }
    this->Internals->CurrentKey = key;
  }
  const int wanted = this->StepAsked(outInfo);
  const int computed = this->Internals->Current->computedSteps();
  const auto begin = std::chrono::steady_clock::now();
  const bool advanced = this->Advance(wanted);
  this->Internals->ComputeSeconds += secondsSince(begin);
  if (advanced)
  {
    // The end of a run: the last step, computed now.
    const bool finished =
      wanted == this->NumberOfSteps && this->Internals->Current->computedSteps() > computed;
    this->WriteOutput(wanted, finished, output);
  }
  // The pipeline takes an execution as up to date even when a property changed while it ran (a
  // panel edit, a script's callback): RunAgain makes the next request run again, with the new values.
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
    vtkWarningMacro("Number Of Steps is 0: showing the starting surface.");
  }
  const int computed = this->Internals->Current->computedSteps();
  bool finished = false;
  onAllCores([&] { finished = this->Internals->Current->advanceTo(step, this->ProgressOf(0, 1)); });
  // An abort ends this run: the empty output stands until a property, an input or the time asked
  // for changes (then the run resumes from the cache, or starts over).
  if (!finished)
  {
    this->AbortExecute = 0; // honoured; a set flag would stop every later run at its first step
    vtkWarningMacro("Shrink Wrap was aborted; the output is empty (computed steps stay cached).");
    return false;
  }
  if (this->Internals->Current->lastGood() >= 0 && this->Internals->Current->computedSteps() > computed)
  {
    vtkWarningMacro("The evolution failed: " << this->Internals->Current->failure()
                                             << "; later times show step "
                                             << this->Internals->Current->lastGood() << ".");
  }
  return true;
}

void vtkShrinkWrapFilter::WriteOutput(int wanted, bool finished, vtkPolyData* output)
{
  const WrapSession& s = *this->Internals->Current;
  const WrapSession::Surface surface = s.surface(wanted);
  SurfaceMesh mesh;
  if (const Status closed = SurfaceMesh::build(surface.points, *surface.cached->triangles, mesh);
      !closed)
  {
    vtkErrorMacro("Internal error: step " << surface.step << " is not a closed surface: "
                                          << closed.message() << ".");
    return;
  }
  convert::writeSurface(
    surface.points, mesh, s.fields().target, surface.cached->tangentialVelocity, output);
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
    vtkWarningMacro("The surface of step " << surface.step << " passes through itself ("
                                           << crossings.pairs
                                           << " triangle pairs cross; cell array SelfIntersecting).");
  }
  convert::addStepFields(surface.step, surface.step * this->TimeStep, status, output);
  this->ShowSizes(s.plan().sizes());
  const convert::WrapSummary summary =
    convert::summarize(output, s.plan().sizes(), surface.step, this->Internals->ComputeSeconds);
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
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "FlipDihedralLimit: " << this->FlipDihedralLimit << "\n";
  os << indent << "StartingShape: " << this->StartingShape << "\n";
  os << indent << "StartOffset: " << this->StartOffset << "\n";
  os << indent << "GapSize: " << this->GapSize << "\n";
  os << indent << "CloseHoles: " << this->CloseHoles << "\n";
  os << indent << "Remeshing: " << this->Remeshing << "\n";
  os << indent << "TargetEdgeLength: " << this->TargetEdgeLength << "\n";
  os << indent << "EdgeLengthRange: " << this->EdgeLengthRange[0] << " " << this->EdgeLengthRange[1]
     << "\n";
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
