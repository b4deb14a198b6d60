#include "WrapRuns.h"

#include "RankInputs.h"
#include "TargetInput.h"
#include "VTKConversions.h"

#include "Wrap/AutomaticSizes.h"
#include "Wrap/Wrap.h"

#include <vtkAlgorithm.h>
#include <vtkCompositeDataSet.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace shrinkwrap
{
namespace convert
{

namespace
{
// The field and the start given beside the target, into `target`.
Status readGiven(const WrapInputs& inputs, WrapTarget& target)
{
  if (inputs.field)
  {
    DistanceGrid grid;
    if (Status read = gridOf(inputs.field, "SignedDistance", grid); !read)
    {
      return read;
    }
    target.fieldLattice = grid.lattice();
    target.field = std::make_shared<const DistanceGrid>(std::move(grid));
  }
  target.givenStart = inputs.start != nullptr;
  if (inputs.start)
  {
    TriangleSoup given;
    if (!surfaceOf(inputs.start, given))
    {
      return Status::failure("the Initial Surface must be made of triangles only, with finite "
                             "points and valid point ids");
    }
    target.start = std::make_shared<const TriangleSoup>(std::move(given));
  }
  return {};
}
} // namespace

Status wrapInputs(
  vtkInformationVector** inputVector, WrapInputs& inputs, std::optional<GridLattice>& fieldLattice)
{
  inputs = WrapInputs();
  inputs.field = vtkImageData::GetData(inputVector[1], 0);
  inputs.start = vtkPolyData::GetData(inputVector[2], 0);
  int targets = 0;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    vtkDataObject* data = vtkDataObject::GetData(inputVector[0], c);
    auto* image = vtkImageData::SafeDownCast(data);
    if (image && image->GetPointData()->GetArray("SignedDistance") &&
      (!inputs.field || image == inputs.field)) // the field, on Input or on both ports
    {
      inputs.field = image;
      continue;
    }
    inputs.target = data;
    targets += data != nullptr;
  }
  fieldLattice.reset();
  for (int port = 0; port < 2 && inputs.field; ++port)
  {
    for (int c = 0; c < inputVector[port]->GetNumberOfInformationObjects(); ++c)
    {
      vtkInformation* info = inputVector[port]->GetInformationObject(c);
      if (info->Get(vtkDataObject::DATA_OBJECT()) == inputs.field)
      {
        fieldLattice = latticeOf(inputs.field);
        if (const double* h =
              info->Has(vtkDataObject::SPACING()) ? info->Get(vtkDataObject::SPACING()) : nullptr)
        {
          fieldLattice->spacing = Vec3(h[0], h[1], h[2]);
        }
      }
    }
  }
  return targets <= 1
    ? Status()
    : Status::failure("Shrink Wrap wraps one target at a time, and its Input holds " +
        std::to_string(targets) + " (besides a distance field)");
}

void advertiseSteps(vtkInformation* outInfo, int steps, double timeStep)
{
  const double tau = timeStep > 0 ? timeStep : 1.0;
  std::vector<double> times(steps + 1);
  for (int k = 0; k <= steps; ++k)
  {
    times[k] = k * tau;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), steps + 1);
  const double range[2] = { 0.0, steps * tau };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
}

int stepAsked(vtkInformation* outInfo, int steps, double timeStep)
{
  const double asked = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) / timeStep
    : std::nan("");
  if (std::isnan(asked))
  {
    return steps;
  }
  return asked <= 0 ? 0 : (asked >= steps ? steps : static_cast<int>(std::lround(asked)));
}

std::vector<int> piecesOfBlocks(
  const std::vector<vtkDataSet*>& targets, int pieces, WrapSettings settings)
{
  settings.remeshing = true;
  std::vector<double> cost(targets.size(), 1.0);
  for (std::size_t b = 0; b < targets.size(); ++b)
  {
    SoupCounts counts;
    const TriangleSoup soup = soupOf(polygonMeshes(targets[b]).meshes, counts);
    const Box box = boundsOf(targets[b]);
    const double length = box.empty() ? 0.0 : edgeLengthFor(settings, box).value_or(0);
    const double vertices = soup.area() / (length * length);
    cost[b] = length > 0 && std::isfinite(vertices) ? std::max(1.0, vertices) : 1.0;
  }
  return shareOut(cost, pieces);
}

vtkMTimeType WrapRuns::keyOf(vtkAlgorithm* filter, int ports)
{
  std::vector<InputDigest> digests;
  std::uint64_t key = filter->GetMTime();
  for (int port = 0; port < ports; ++port)
  {
    for (int c = 0; c < filter->GetNumberOfInputConnections(port); ++c)
    {
      vtkDataObject* data = filter->GetInputDataObject(port, c);
      if (!data)
      {
        continue;
      }
      const auto known = std::find_if(this->Digests.begin(), this->Digests.end(),
        [&](const InputDigest& d) { return d.data == data && d.time == data->GetMTime(); });
      digests.push_back(known != this->Digests.end()
          ? *known
          : InputDigest{ data, data->GetMTime(), contentDigest(data) });
      key = key * 0x100000001b3ull ^ digests.back().digest; // FNV-1a's prime: one 64-bit key
    }
  }
  this->Digests = std::move(digests);
  return static_cast<vtkMTimeType>(key);
}

void WrapRuns::keepBlocksFor(vtkMTimeType key)
{
  if (key != this->BlocksKey)
  {
    for (auto run = this->Runs.begin(); run != this->Runs.end();)
    {
      run = run->first > 0 ? this->Runs.erase(run) : std::next(run);
    }
    this->Shares.clear();
    this->BlocksKey = key;
  }
}

void WrapRuns::clear()
{
  this->Runs.clear();
}

int WrapRuns::computedSteps() const
{
  int steps = 0;
  for (const auto& run : this->Runs)
  {
    steps += run.second.session ? run.second.session->computedSteps() : 0;
  }
  return steps;
}

const WrapRuns::ConvertedTarget& WrapRuns::TargetOf(vtkDataObject* data, int inputGeometry)
{
  ConvertedTarget& c = this->Converted;
  if (c.data == data && c.key == data->GetMTime() && c.geometry == inputGeometry)
  {
    return c;
  }
  c = ConvertedTarget{ data, data->GetMTime(), inputGeometry };
  vtkSmartPointer<vtkDataObject> whole = data;
  if (vtkCompositeDataSet::SafeDownCast(data))
  {
    whole = appendedLeaves(data);
  }
  c.status = wrapTarget(whole, inputGeometry, c.target, c.notes);
  return c;
}

const WrapPlan* WrapRuns::plan(vtkDataObject* data, const std::optional<GridLattice>& field,
  bool givenStart, vtkMTimeType key, int inputGeometry, const WrapSettings& settings)
{
  PlannedWrap& p = this->Planned;
  const bool same = p.key == key && p.data == data && p.givenStart == givenStart &&
    p.field.has_value() == field.has_value() && (!field || *p.field == *field);
  if (!same)
  {
    const ConvertedTarget& converted = this->TargetOf(data, inputGeometry);
    p = PlannedWrap{ key, data, field, givenStart, converted.status };
    WrapTarget target = converted.target;
    target.fieldLattice = field;
    target.givenStart = givenStart;
    if (p.status)
    {
      p.status = planWrap(target, settings, p.plan);
    }
  }
  return p.status ? &p.plan : nullptr;
}

void WrapRuns::keepFramesFor(vtkMTimeType key)
{
  if (key != this->FramesKey)
  {
    this->Frames.clear();
    for (auto& slot : this->Runs)
    {
      slot.second = Run();
    }
    this->FramesKey = key;
  }
}

void WrapRuns::followTimes(const std::vector<double>& times)
{
  if (this->Frames.follow(times))
  {
    for (auto& slot : this->Runs)
    {
      slot.second.series = Run::Series();
    }
  }
}

bool WrapRuns::startFrame(Run& run, int frame, const WrapInputs& inputs, vtkMTimeType key,
  int inputGeometry, WrapSettings settings, const Progress& progress, Notes& notes, Status& status,
  FrameReport& report)
{
  Run::Series series = std::move(run.series);
  if (series.newestFrame != frame - 1)
  {
    series = Run::Series(); // the series starts over
  }
  run = Run();
  if (!inputs.target)
  {
    status = Status::failure("there is no target");
    return false;
  }
  if (series.sizes) // the first frame's
  {
    settings.gapSize = series.sizes->gap;
    settings.targetEdgeLength = series.sizes->edgeLength;
  }
  const ConvertedTarget& converted = this->TargetOf(inputs.target, inputGeometry);
  notes.insert(notes.end(), converted.notes.begin(), converted.notes.end());
  WrapTarget target = converted.target;
  status = converted.status;
  if (status)
  {
    status = readGiven(inputs, target);
  }
  WrapPlan plan; // planned for this frame alone: the sizes differ from the panel's plan
  if (status)
  {
    status = planWrap(target, settings, plan);
  }
  if (status)
  {
    const FollowedWrap* previous = series.newest ? &*series.newest : nullptr;
    status = wrapFrame(
      target, plan, previous, FollowSettings(), contour, progress, notes, run.session, report);
  }
  run.key = status ? key : 0;
  run.polygons = target.polygons;
  run.cloud = target.polygons ? nullptr : target.points;
  run.measuredOn = run.session ? run.session->fields().target.exactShared() : nullptr;
  if (status)
  {
    const std::int64_t nextTrack = series.newest ? series.newest->nextTrack : 0;
    series.newest = followedWrap(*run.session, report.steps, target.polygons, nextTrack);
    series.newestFrame = frame;
    series.sizes = series.sizes ? series.sizes : plan.sizes();
  }
  run.series = std::move(series);
  return status.ok();
}

bool WrapRuns::start(Run& run, const WrapInputs& inputs, vtkMTimeType key, int inputGeometry,
  const WrapSettings& settings, const Progress& progress, Notes& notes, Status& status)
{
  run = Run();
  if (!inputs.target)
  {
    status = Status::failure("there is no target");
    return false;
  }
  WrapTarget target = this->TargetOf(inputs.target, inputGeometry).target;
  status = readGiven(inputs, target);
  const WrapPlan* plan = status ? this->plan(inputs.target, target.fieldLattice, target.givenStart,
                                    key, inputGeometry, settings)
                                : nullptr;
  const Notes& read = this->targetNotes();
  notes.insert(notes.end(), read.begin(), read.end());
  if (status && !plan)
  {
    status = this->status();
  }
  if (status)
  {
    status = startWrap(target, *plan, contour, progress, notes, run.session);
  }
  run.key = status ? key : 0;
  run.polygons = target.polygons;
  run.cloud = target.polygons ? nullptr : target.points;
  run.measuredOn = run.session ? run.session->fields().target.exactShared() : nullptr;
  return status.ok();
}

} // namespace convert
} // namespace shrinkwrap
