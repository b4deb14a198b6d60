#include "vtkShrinkWrapFilter.h"

#include "PropertyBinding.h"
#include "RankInputs.h"
#include "ShrinkWrapProperties.h"
#include "TargetData.h"
#include "VTKConversions.h"
#include "WrapOutput.h"
#include "WrapRuns.h"

#include "Common/Parallel.h"
#include "Distance/DistanceSource.h"
#include "Wrap/AutomaticSizes.h"

#include "vtkCommunicator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkShrinkWrapFilter);
vtkCxxSetObjectMacro(vtkShrinkWrapFilter, Controller, vtkMultiProcessController);

using namespace shrinkwrap;

namespace
{
double secondsSince(std::chrono::steady_clock::time_point begin)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

} // namespace

vtkShrinkWrapFilter::vtkShrinkWrapFilter()
  : Runs(new convert::WrapRuns)
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2); // the wrap, the target as measured
  this->SetProperties(WrapSettings());
  this->SetProgressText("Shrink Wrap");
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkShrinkWrapFilter::~vtkShrinkWrapFilter()
{
  this->SetController(nullptr);
}

std::vector<convert::PropertyInfo> vtkShrinkWrapFilter::DescribeProperties()
{
  std::vector<convert::PropertyInfo> described{ kInputGeometry, kWrapPerBlock, kPassTargetArrays,
    kTimeMode };
  const WrapSettings settings;
  vtkNew<vtkShrinkWrapFilter> filter;
  BindProperties(*filter.Get(), settings,
    [&](const convert::PropertyInfo& p, const auto&, const auto&) { described.push_back(p); });
  return described;
}

Status vtkShrinkWrapFilter::CheckProperties() const
{
  Status status = convert::checkProperty(kInputGeometry, this->InputGeometry);
  if (status)
  {
    status = convert::checkProperty(kTimeMode, this->TimeMode);
  }
  const WrapSettings unused;
  BindProperties(
    *this, unused, [&](const convert::PropertyInfo& info, const auto& property, const auto&) {
      if (status)
      {
        status = convert::checkProperty(info, property);
      }
    });
  return status;
}

void vtkShrinkWrapFilter::SetProperties(const WrapSettings& settings)
{
  BindProperties(
    *this, settings, [](const convert::PropertyInfo&, auto& property, const auto& setting) {
      convert::assign(property, setting);
    });
  this->Modified();
}

WrapSettings vtkShrinkWrapFilter::CoreSettings() const
{
  WrapSettings settings;
  BindProperties(
    *this, settings, [](const convert::PropertyInfo&, const auto& property, auto& setting) {
      convert::assign(setting, property);
    });
  return settings;
}

void vtkShrinkWrapFilter::SetPassTargetArrays(bool pass)
{
  if (pass != this->PassTargetArrays)
  {
    // Not a change of the wrap: the next update writes the cached steps again, with or without.
    this->PassTargetArrays = pass;
    this->RunAgain = true;
  }
}

int vtkShrinkWrapFilter::GetNumberOfComputedSteps() const
{
  return this->Runs->computedSteps();
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
  // A composite target gives a composite of the same kind (a wrap per block), else a surface.
  // The target as measured is a composite of the same kind for a composite target.
  vtkCompositeDataSet* composite = convert::compositeOf(inputVector[0]);
  vtkCompositeDataSet* blocks = this->WrapPerBlock ? composite : nullptr;
  if (convert::makeOutput<vtkPolyData>(request, outputVector, blocks))
  {
    return convert::makeOutput<vtkPolyData>(request, outputVector, composite, 1);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkShrinkWrapFilter::ComputePipelineMTime(vtkInformation* request,
  vtkInformationVector** inInfoVec, vtkInformationVector* outInfoVec, int requestFromOutputPort,
  vtkMTimeType* mtime)
{
  const int result = this->Superclass::ComputePipelineMTime(
    request, inInfoVec, outInfoVec, requestFromOutputPort, mtime);
  this->PipelineTime = *mtime; // the filter's and its inputs' pipelines: what keys the frames
  // Asked of the wrap (port 0): the target as measured, updated after it in the same update (a
  // proxy's UpdatePipeline updates every port), is what that run measured.
  if (this->RunAgain && requestFromOutputPort <= 0)
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
  this->ShowSizes({});
  if (!this->CheckProperties())
  {
    return 1; // RequestData says why
  }
  // Every evolution step is a time step of both outputs, or every frame of the target.
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  const int frames = in ? in->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) : 0;
  this->FollowsTarget =
    this->TimeMode == TIME_FOLLOW_TARGET || (this->TimeMode == TIME_AUTOMATIC && frames > 0);
  std::vector<double> times;
  if (frames > 0)
  {
    const double* t = in->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    times.assign(t, t + frames);
  }
  this->Runs->followTimes(
    this->FollowsTarget && times.empty() ? std::vector<double>{ 0.0 } : times);
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* out = outputVector->GetInformationObject(port);
    if (!this->FollowsTarget)
    {
      convert::advertiseSteps(out, this->NumberOfSteps, this->TimePerStep);
    }
    else if (frames > 0)
    {
      out->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), frames);
      const double range[2] = { times.front(), times.back() };
      out->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    }
    else
    {
      out->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      out->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    }
  }
  // ParaView reads information properties after RequestInformation, not after RequestData: the
  // panel's sizes are planned here from the inputs as they stand (0 while the target has not been
  // computed, and for a composite wrapped block by block); RequestData then shows the run's.
  convert::WrapInputs inputs;
  std::optional<GridLattice> field;
  const bool one = convert::wrapInputs(inputVector, inputs, field).ok();
  const bool blockByBlock = vtkCompositeDataSet::SafeDownCast(inputs.target) && this->WrapPerBlock;
  if (one && inputs.target && !blockByBlock)
  {
    onAllCores([&] { // a cloud's spacing is measured on all cores
      const WrapPlan* plan = this->Runs->plan(inputs.target, field, inputs.start != nullptr,
        this->SessionKey(), this->InputGeometry, this->CoreSettings());
      this->ShowSizes(plan ? plan->sizes() : WrapSizes());
    });
  }
  return 1;
}

void vtkShrinkWrapFilter::ShowSizes(const WrapSizes& sizes)
{
  this->FieldCellSize = sizes.cell;
  this->ChosenGapSize = sizes.gap;
  this->ChosenEdgeLength = sizes.edgeLength.value_or(0); // 0: Remeshing off
}

int vtkShrinkWrapFilter::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The whole target, field and starting surface: whatever time is asked of the output, or
  // following the target, each frame in turn up to the one at the time asked.
  convert::askWholeInputs(inputVector, 3, true);
  if (!this->FollowsTarget)
  {
    return 1;
  }
  FrameSchedule& schedule = this->Runs->frames();
  this->Runs->keepFramesFor(this->PipelineTime);
  if (!this->FrameContinues) // an update begins
  {
    const int port = std::clamp(request->Get(vtkExecutive::FROM_OUTPUT_PORT()), 0, 1);
    vtkInformation* out = outputVector->GetInformationObject(port);
    const double asked = out->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      ? out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      : std::nan("");
    this->FrameWanted = schedule.frameAt(asked);
    this->FrameAsked = this->FrameFirst = schedule.next(this->FrameWanted);
    this->FrameLoopTime = this->GetMTime();
  }
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  if (in && in->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    const double time = schedule.times()[this->FrameAsked];
    for (int port = 0; port < 2; ++port) // the target, and a distance field that has times
    {
      for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
      {
        vtkInformation* info = inputVector[port]->GetInformationObject(c);
        if (info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
        {
          info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), time);
        }
      }
    }
  }
  return 1;
}

vtkMTimeType vtkShrinkWrapFilter::SessionKey()
{
  return this->Runs->keyOf(this, 3);
}

int vtkShrinkWrapFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The time and piece asked for are the asking port's (the target as measured is shown alone too).
  const int asking = std::clamp(request->Get(vtkExecutive::FROM_OUTPUT_PORT()), 0, 1);
  vtkInformation* outInfo = outputVector->GetInformationObject(asking);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  vtkDataObject* measured = vtkDataObject::GetData(outputVector, 1);
  output->Initialize();
  measured->Initialize();
  this->FrameStopped = false; // set by this execution when a followed series cannot go on
  if (const Status checked = this->CheckProperties(); !checked)
  {
    vtkErrorMacro(<< "Cannot wrap: " << checked.message() << ".");
    return 1;
  }
  vtkCompositeDataSet* blocks = this->WrapPerBlock ? convert::compositeOf(inputVector[0]) : nullptr;
  this->SetProgressShiftScale(0, 1); // (a run that threw may have left a block's share)
  try // memory can run out below any estimate (a process limit, a job's cap)
  {
    if (blocks)
    {
      this->ExecuteBlocks(
        blocks, inputVector, outInfo, vtkCompositeDataSet::SafeDownCast(output), measured);
    }
    else
    {
      this->ExecuteWhole(inputVector, outInfo, vtkPolyData::SafeDownCast(output), measured);
    }
  }
  catch (const std::exception& e) // std::bad_alloc, threads that cannot start under the same limits
  {
    this->FrameStopped = true; // a followed series ends its update here
    output->Initialize();
    measured->Initialize();
    this->Runs->clear(); // a half-made step is not kept; the next update starts over
    if (dynamic_cast<const std::bad_alloc*>(&e))
    {
      vtkErrorMacro("Out of memory: lower Subdivision Level, Resolution or Cache Memory (MiB).");
    }
    else
    {
      vtkErrorMacro("Shrink Wrap failed: " << e.what() << ".");
    }
  }
  if (this->FollowsTarget)
  {
    this->NextFrame(request, outputVector);
  }
  // The target as measured stands at the wrap's time, whichever port asked.
  if (output->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    measured->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(),
      output->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()));
  }
  return 1;
}

// Each block of a composite target is wrapped on its own, with a session (and a cache) of its own;
// under MPI the blocks are shared out among the pieces by their expected cost (piecesOfBlocks; the
// other pieces leave a block empty), so the ranks wrap them in parallel.
void vtkShrinkWrapFilter::ExecuteBlocks(vtkCompositeDataSet* blocks,
  vtkInformationVector** inputVector, vtkInformation* outInfo, vtkCompositeDataSet* output,
  vtkDataObject* measured)
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
  // (A followed series keeps its blocks' frames while the pipeline stays: RequestUpdateExtent.)
  this->Runs->keepBlocksFor(this->FollowsTarget ? this->PipelineTime : this->SessionKey());
  const std::vector<vtkDataSet*> targets = convert::leavesOf(blocks);
  // Shared out once per target and properties, not at every time asked for.
  const std::vector<int> wrappedOn =
    convert::piecesOfLeaves(blocks, targets, request, this->Controller, [&] {
      return this->Runs->blockPieces(request.pieces, [&] {
        return request.pieces > 1
          ? convert::piecesOfBlocks(targets, request.pieces, this->CoreSettings())
          : std::vector<int>(targets.size(), 0);
      });
    });
  std::map<unsigned int, vtkSmartPointer<vtkPolyData>> measuredLeaves;
  convert::computeLeaves<vtkPolyData>(blocks, output, wrappedOn, request.piece,
    [&](vtkDataSet* target, unsigned int index, vtkPolyData* wrap, double first, double share) {
      this->SetProgressShiftScale(first, share); // one progress bar over the blocks
      auto& leaf = measuredLeaves[index] = vtkSmartPointer<vtkPolyData>::New();
      this->Execute(1 + index, { target, nullptr, nullptr }, outInfo, wrap, leaf);
    });
  // The target as measured: each block against its own wrap, empty where another piece wraps it.
  if (auto* measuredBlocks = vtkCompositeDataSet::SafeDownCast(measured))
  {
    measuredBlocks->CopyStructure(blocks);
    auto at = vtkSmartPointer<vtkCompositeDataIterator>::Take(blocks->NewIterator());
    for (at->InitTraversal(); !at->IsDoneWithTraversal(); at->GoToNextItem())
    {
      const auto found = measuredLeaves.find(at->GetCurrentFlatIndex());
      measuredBlocks->SetDataSet(
        at, found != measuredLeaves.end() ? found->second : vtkSmartPointer<vtkPolyData>::New());
    }
  }
  this->SetProgressShiftScale(0, 1);
  this->ShowSizes({}); // each block had sizes of its own
}

// Every rank takes part (the target is made whole on each); piece 0 wraps it, under MPI the other
// pieces are empty.
void vtkShrinkWrapFilter::ExecuteWhole(vtkInformationVector** inputVector, vtkInformation* outInfo,
  vtkPolyData* output, vtkDataObject* measured)
{
  convert::WrapInputs inputs;
  std::optional<GridLattice> lattice;
  const Status one = convert::wrapInputs(inputVector, inputs, lattice);
  if (!one)
  {
    vtkErrorMacro(<< one.message() << ".");
    this->FrameStopped = true; // (following a series: its update ends here)
  }
  inputs.target =
    convert::wholeInput(one ? inputs.target : nullptr, this->Controller, this->Gathered);
  if (one && convert::pieceRequest(outInfo).piece == 0)
  {
    this->Execute(0, inputs, outInfo, output, measured);
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

// The run of `slot`, started on `inputs` when there is none for the inputs and properties as they
// are (any change drops its cache), advanced to the step asked for, into `output`.
void vtkShrinkWrapFilter::Execute(unsigned int slot, const convert::WrapInputs& inputs,
  vtkInformation* outInfo, vtkPolyData* output, vtkDataObject* measured)
{
  if (this->FollowsTarget)
  {
    this->ExecuteFrame(slot, inputs, output, measured);
    return;
  }
  const vtkMTimeType key = this->SessionKey();
  convert::WrapRuns::Run& run = this->Runs->run(slot);
  const auto begin = std::chrono::steady_clock::now();
  Notes notes;
  // A run started here reports its setup as the first part of the progress, its steps the rest.
  double stepsFrom = 0;
  if (!run.session || run.key != key)
  {
    Status status;
    bool started = false;
    stepsFrom = kSetupShare;
    onAllCores([&] {
      started = this->Runs->start(run, inputs, key, this->InputGeometry, this->CoreSettings(),
        this->ProgressOf(0, stepsFrom), notes, status);
    });
    convert::report(this, "Shrink Wrap", notes);
    notes.clear();
    if (!started && this->GetAbortExecute())
    {
      this->AbortExecute = 0; // honoured, as an abort during the steps (Advance)
      vtkWarningMacro("Shrink Wrap was aborted while it set up; the output is empty.");
      return;
    }
    if (!started)
    {
      vtkErrorMacro("Cannot wrap: " << status.message() << ".");
      return;
    }
  }
  const int wanted = convert::stepAsked(outInfo, this->NumberOfSteps, this->TimePerStep);
  const int computed = run.session->computedSteps();
  const bool advanced = this->Advance(*run.session, wanted, stepsFrom);
  run.seconds += secondsSince(begin);
  // The end of a run: the last step, computed now.
  const bool finished = wanted == this->NumberOfSteps && run.session->computedSteps() > computed;
  if (advanced)
  {
    // The target is measured against the written wrap: sampled distances for the summary of its
    // last step, then its data carried over and the target as measured.
    const bool pass = this->PassTargetArrays && convert::hasArraysToPass(inputs.target);
    const vtkSmartPointer<vtkDataObject> whole =
      pass ? convert::wholeTarget(inputs.target) : nullptr;
    if (pass && run.polygons && !run.carrier)
    {
      // Before the closeness lets the session's distance go: the carrier reads through it.
      run.carrier = convert::makeCarrier(whole, run.polygons, run.measuredOn);
    }
    const bool last = run.session->shown(wanted) == this->NumberOfSteps;
    std::unique_ptr<TriangleSource> wrap;
    const Status written = convert::writeWrap(*run.session, wanted, this->TimePerStep, run.seconds,
      finished, output, notes, this->MeasureWrap(slot, last, wrap));
    if (written && wrap)
    {
      this->CarryAndMeasure(
        slot, inputs.target, whole, *wrap, last, finished, output, measured, notes);
    }
    this->ShowSizes(run.session->plan().sizes());
    convert::report(this, "Shrink Wrap", notes);
    if (!written)
    {
      vtkErrorMacro("Internal error: " << written.message() << ".");
    }
  }
  // The pipeline takes an execution as up to date even when a property changed while it ran (a
  // panel edit, a script's callback): RunAgain makes the next request run again, with the new
  // values.
  if (this->SessionKey() != key)
  {
    this->RunAgain = true;
    vtkWarningMacro(
      "Properties or inputs changed during the run; they apply from the next update.");
  }
}

namespace
{
// A copy of `data` that shares its arrays but not its field data's list (arrays added to one do not
// show on the other).
template <typename T>
vtkSmartPointer<T> copyOf(T* data)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->ShallowCopy(data);
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(data->GetFieldData());
  copy->SetFieldData(fields);
  return copy;
}

// TrackId, Displacement and Velocity (Displacement over `dt`; zero where dt is not positive) of a
// followed frame, as point arrays of `output` (its points in the wrap's order).
void addMotion(const FollowedWrap& wrap, double dt, vtkPolyData* output)
{
  const vtkIdType n = output->GetNumberOfPoints();
  const VertexProperty<TrackId> tracks = wrap.mesh.vertexProperty<TrackId>(kTrackProperty);
  if (!tracks || static_cast<vtkIdType>(wrap.displacement.size()) != n)
  {
    return;
  }
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("TrackId");
  ids->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> displacement, velocity;
  displacement->SetName("Displacement");
  velocity->SetName("Velocity");
  for (vtkDoubleArray* a : { displacement.Get(), velocity.Get() })
  {
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(n);
  }
  const double rate = dt > 0 ? 1 / dt : 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    ids->SetValue(i, static_cast<vtkIdType>(tracks[static_cast<int>(i)].id));
    const Vec3& d = wrap.displacement[i];
    displacement->SetTuple3(i, d.x(), d.y(), d.z());
    velocity->SetTuple3(i, rate * d.x(), rate * d.y(), rate * d.z());
  }
  output->GetPointData()->AddArray(ids);
  output->GetPointData()->AddArray(displacement);
  output->GetPointData()->AddArray(velocity);
}

// The field data value `name` of `data` set to `value` (a one-value array).
void setField(vtkDataObject* data, const char* name, double value)
{
  if (auto* a = vtkDoubleArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name)))
  {
    a->SetValue(0, value);
  }
}
} // namespace

void vtkShrinkWrapFilter::ExecuteFrame(unsigned int slot, const convert::WrapInputs& inputs,
  vtkPolyData* output, vtkDataObject* measured)
{
  const int frame = this->FrameAsked;
  const FrameSchedule& schedule = this->Runs->frames();
  const bool timed =
    this->GetInputInformation(0, 0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double time = timed ? schedule.times()[frame] : 0;
  convert::WrapRuns::Run& run = this->Runs->run(slot);
  Notes notes;
  if (!run.series.frames.count(frame))
  {
    const double share = 1.0 / std::max(this->FrameWanted - this->FrameFirst + 1, 1);
    const double from = std::clamp((frame - this->FrameFirst) * share, 0.0, 1.0 - share);
    const auto begin = std::chrono::steady_clock::now();
    Status status;
    FrameReport report;
    bool started = false;
    onAllCores([&] {
      started = this->Runs->startFrame(run, frame, inputs, this->SessionKey(), this->InputGeometry,
        this->CoreSettings(), this->ProgressOf(from, from + share), notes, status, report);
    });
    convert::report(this, "Shrink Wrap", notes);
    notes.clear();
    if (!started)
    {
      this->FrameStopped = true;
      if (this->GetAbortExecute())
      {
        this->AbortExecute = 0;
        vtkWarningMacro("Shrink Wrap was aborted at frame "
          << frame << "; the output is empty (the frames before it stay cached).");
      }
      else
      {
        vtkErrorMacro("Cannot wrap frame " << frame << ": " << status.message() << ".");
      }
      return;
    }
    run.seconds = secondsSince(begin);
    const bool wanted = frame == this->FrameWanted;
    std::unique_ptr<TriangleSource> wrap;
    const Status written = convert::writeWrap(*run.session, report.steps, this->TimePerStep,
      run.seconds, wanted, output, notes, this->MeasureWrap(slot, wanted, wrap));
    if (!written || !wrap)
    {
      this->FrameStopped = true;
      vtkErrorMacro("Internal error: " << written.message() << ".");
      return;
    }
    const double before = frame > 0 && timed ? schedule.times()[frame - 1] : time;
    addMotion(*run.series.newest, report.carried ? time - before : 0.0, output);
    setField(output, "Time", time);
    if (!report.fresh.empty())
    {
      auto* statuses =
        vtkStringArray::SafeDownCast(output->GetFieldData()->GetAbstractArray("Status"));
      if (statuses && statuses->GetValue(0) == "ok")
      {
        statuses->SetValue(0, "started afresh: " + report.fresh);
      }
      warn(notes,
        "Frame " + std::to_string(frame) + " started afresh: " + report.fresh +
          " (its vertices get new TrackIds)");
    }
    // The largest distance over the target's surface for the frame asked for (frames on the way to
    // it go without: its search is the costliest part of the measuring).
    this->CarryAndMeasure(
      slot, inputs.target, nullptr, *wrap, wanted, wanted, output, measured, notes);
    convert::report(this, "Shrink Wrap", notes);
    this->ShowSizes(run.session->plan().sizes());
    run.series.frames[frame] = { copyOf(output), copyOf(measured) };
    run.session.reset(); // the frame's fields: the next frame makes its own
    run.measuredOn.reset();
    this->ThinFrames(slot);
  }
  else
  {
    const auto& cached = run.series.frames[frame];
    output->ShallowCopy(copyOf(cached.wrap.Get()));
    measured->ShallowCopy(copyOf(cached.measured.Get()));
  }
  // The target's arrays, read from this frame's target.
  const WrapTarget* target = this->PassTargetArrays && convert::hasArraysToPass(inputs.target)
    ? this->Runs->converted(inputs.target, this->InputGeometry)
    : nullptr;
  if (target)
  {
    const vtkSmartPointer<vtkDataObject> whole = convert::wholeTarget(inputs.target);
    const auto carrier =
      target->polygons ? convert::makeCarrier(whole, target->polygons, nullptr) : nullptr;
    std::vector<std::string> renamed;
    onAllCores([&] {
      convert::passTargetArrays(
        whole, carrier.get(), target->polygons ? nullptr : target->points.get(), output, renamed);
    });
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
}

// Keeps the frames' outputs within Cache Memory (MiB): the oldest are dropped but the first and
// the newest (a frame dropped is computed again, from the first, when asked for).
void vtkShrinkWrapFilter::ThinFrames(unsigned int slot)
{
  auto& frames = this->Runs->run(slot).series.frames;
  auto kib = [](const convert::WrapRuns::Run::Frame& f) {
    return static_cast<double>(f.wrap->GetActualMemorySize() + f.measured->GetActualMemorySize());
  };
  double total = 0;
  for (const auto& f : frames)
  {
    total += kib(f.second);
  }
  for (auto f = std::next(frames.begin());
       total > this->CacheMemoryMiB * 1024 && frames.size() > 2 && f != std::prev(frames.end());)
  {
    total -= kib(f->second);
    this->Runs->frames().forget(f->first);
    f = frames.erase(f);
  }
}

void vtkShrinkWrapFilter::NextFrame(vtkInformation* request, vtkInformationVector* outputVector)
{
  const int frame = this->FrameAsked;
  FrameSchedule& schedule = this->Runs->frames();
  if (frame < 0)
  {
    return;
  }
  // A property edited during the series (a panel edit, a script's callback): the series stops here
  // and starts over with the new values at the next update.
  if (!this->FrameStopped && frame < this->FrameWanted && this->GetMTime() != this->FrameLoopTime)
  {
    vtkWarningMacro("Properties changed while the series was followed (frame "
      << frame << "); it starts over with them at the next update.");
    this->FrameStopped = true;
    this->RunAgain = true;
  }
  // Every rank goes on to the next frame together (each takes part in gathering the target).
  if (this->Controller && this->Controller->GetNumberOfProcesses() > 1)
  {
    int stopped = this->FrameStopped, anywhere = 0;
    this->Controller->AllReduce(&stopped, &anywhere, 1, vtkCommunicator::MAX_OP);
    this->FrameStopped = anywhere != 0;
  }
  if (!this->FrameStopped && !schedule.done(frame))
  {
    schedule.markDone(frame);
  }
  if (!this->FrameStopped && frame < this->FrameWanted)
  {
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    this->FrameAsked = frame + 1;
    this->FrameContinues = true;
  }
  else
  {
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    this->FrameAsked = -1;
    this->FrameContinues = false;
    this->FrameStopped = false;
  }
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  if (schedule.times().size() > static_cast<std::size_t>(frame) &&
    this->GetInputInformation(0, 0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), schedule.times()[frame]);
  }
}

// The written wrap as a distance source, into `wrap`; with `closeness`, the run's sampled distances
// both ways for its summary.
convert::MeasureWrap vtkShrinkWrapFilter::MeasureWrap(
  unsigned int slot, bool closeness, std::unique_ptr<TriangleSource>& wrap)
{
  return [this, slot, closeness, &wrap](const TriangleSoup& surface) {
    std::optional<Closeness> sampled;
    onAllCores([&] {
      wrap = std::make_unique<TriangleSource>(surface);
      if (closeness)
      {
        sampled = this->LastCloseness(slot, surface, *wrap);
      }
    });
    return sampled;
  };
}

Closeness vtkShrinkWrapFilter::LastCloseness(
  unsigned int slot, const TriangleSoup& surface, const DistanceSource& wrap)
{
  convert::WrapRuns::Run& run = this->Runs->run(slot);
  if (!run.closeness)
  {
    // From the wrap to the target: the session's distance while it holds the target's, else the
    // target's triangles (or points) anew.
    const DistanceSource* source = run.measuredOn ? run.measuredOn.get()
      : run.cloud                                 ? run.cloud->points.get()
                                                  : nullptr;
    std::unique_ptr<AABBTree> tree;
    if (!source && run.polygons)
    {
      tree = std::make_unique<AABBTree>(*run.polygons);
    }
    const SquaredDistance toTarget = [&](const Vec3& p) {
      return source
        ? source->closestPoint(p, std::numeric_limits<double>::infinity()).squaredDistance
        : tree ? tree->closestPoint(p).squaredDistance
               : 0.0;
    };
    run.closeness = measureCloseness(surface, wrap, toTarget, run.polygons.get(),
      run.cloud ? run.cloud->points.get() : nullptr, convert::kSummarySamples);
    run.measuredOn.reset(); // its tree goes with the session's, if the session let it go
  }
  return *run.closeness;
}

void vtkShrinkWrapFilter::CarryAndMeasure(unsigned int slot, vtkDataObject* target,
  vtkDataObject* whole, const DistanceSource& wrap, bool last, bool finished, vtkPolyData* output,
  vtkDataObject* measured, Notes& notes)
{
  convert::WrapRuns::Run& run = this->Runs->run(slot);
  const double gap = run.session->plan().sizes().gap;
  onAllCores([&] {
    if (whole) // arrays to pass
    {
      std::vector<std::string> renamed;
      convert::passTargetArrays(whole, run.carrier.get(), run.cloud.get(), output, renamed);
      if (finished && !renamed.empty())
      {
        std::string names;
        for (const std::string& name : renamed)
        {
          names += (names.empty() ? "" : ", ") + name;
        }
        inform(notes,
          "the target's arrays " + names +
            " have names the wrap uses: they are passed with \" (target)\" added");
      }
    }
    if (auto* blocks = vtkCompositeDataSet::SafeDownCast(measured))
    {
      // A composite wrapped as one: each block measured against the one wrap.
      auto* composite = vtkCompositeDataSet::SafeDownCast(target);
      if (!composite)
      {
        return; // gathered from the ranks as one dataset: no blocks to measure
      }
      blocks->CopyStructure(composite);
      auto at = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
      for (at->InitTraversal(); !at->IsDoneWithTraversal(); at->GoToNextItem())
      {
        if (auto* leaf = vtkDataSet::SafeDownCast(at->GetCurrentDataObject()))
        {
          blocks->SetDataSet(at, convert::measureTarget(leaf, wrap, gap, last));
        }
      }
    }
    else if (auto* one = vtkDataSet::SafeDownCast(target))
    {
      measured->ShallowCopy(convert::measureTarget(one, wrap, gap, last));
    }
  });
}

// Computes the missing steps up to `step`; false when the run was aborted.
bool vtkShrinkWrapFilter::Advance(WrapSession& session, int step, double progressFrom)
{
  if (this->NumberOfSteps == 0)
  {
    vtkWarningMacro("Number Of Steps is 0: showing the starting surface.");
  }
  const int computed = session.computedSteps();
  bool finished = false;
  onAllCores([&] { finished = session.advanceTo(step, this->ProgressOf(progressFrom, 1)); });
  // An abort ends this run: the empty output stands until a property, an input or the time asked
  // for changes (then the run resumes from the cache, or starts over).
  if (!finished)
  {
    this->AbortExecute = 0; // honoured; a set flag would stop every later run at its first step
    vtkWarningMacro("Shrink Wrap was aborted; the output is empty (computed steps stay cached).");
    return false;
  }
  if (session.lastGood() >= 0 && session.computedSteps() > computed)
  {
    vtkWarningMacro("The evolution failed: " << session.failure() << "; later times show step "
                                             << session.lastGood() << ".");
  }
  return true;
}

void vtkShrinkWrapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputGeometry: " << convert::geometryName(this->InputGeometry) << "\n";
  const WrapSettings unused;
  BindProperties(*this, unused, convert::propertyPrinter(os, indent));
  os << indent << "WrapPerBlock: " << this->WrapPerBlock << "\n";
  os << indent << "PassTargetArrays: " << this->PassTargetArrays << "\n";
  os << indent << "TimeMode: " << this->TimeMode << "\n";
  os << indent << "FollowsTarget: " << this->FollowsTarget << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "FieldCellSize: " << this->FieldCellSize << "\n";
  os << indent << "ChosenGapSize: " << this->ChosenGapSize << "\n";
  os << indent << "ChosenEdgeLength: " << this->ChosenEdgeLength << "\n";
}
