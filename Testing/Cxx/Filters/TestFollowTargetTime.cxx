// Shrink Wrap following a target through time (Time Mode): a sphere that translates gives every
// vertex the translation as its Displacement and keeps every TrackId; times between frames, before
// the first and after the last give the frame at or before them, as ParaView's readers do; the
// frames are computed in order and cached (going back asks the target for that frame alone), a
// property edit starts the series over (one made during a series stops it there), an abort leaves
// the frames before it cached; a static target still animates its evolution, and Evolution Steps
// reads a moving target at one time; a Distance Field with times follows too; Cache Memory bounds
// the frames kept.
#include "SeriesSource.h"
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyDataAlgorithm.h>
#include <vtkSphereSource.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

namespace
{
// A sphere of radius 1 at (0.1, 0, 0) t, t = 0, 1, ..., 4.
vtkSmartPointer<vtkPolyData> movedSphere(int t)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkTransform> move;
  move->Translate(0.1 * t, 0, 0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputConnection(sphere->GetOutputPort());
  moved->SetTransform(move);
  moved->Update();
  return moved->GetOutput();
}

vtkSmartPointer<testing::SeriesSource> movingSphere()
{
  auto source = vtkSmartPointer<testing::SeriesSource>::New();
  source->Make = movedSphere;
  source->Frames = 5;
  return source;
}

// The wrap at time t (through the pipeline, as a view asks for it).
vtkPolyData* wrapAt(vtkShrinkWrapFilter* wrap, double t)
{
  wrap->UpdateTimeStep(t);
  return vtkPolyData::SafeDownCast(wrap->GetOutputDataObject(0));
}

double fieldValue(vtkDataObject* data, const char* name)
{
  vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return a ? a->GetTuple1(0) : std::nan("");
}

std::string statusOf(vtkDataObject* data)
{
  auto* a = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("Status"));
  return a ? a->GetValue(0) : "";
}

// Does `act` once, at the first progress event of the wrap while `source` was last asked for
// `frame` (as a user or a script's callback would; the executive's closing event does not repeat
// it).
struct OnceAtFrame
{
  testing::SeriesSource* source;
  double frame;
  std::function<void(vtkShrinkWrapFilter*)> act;
  bool done = false;
  vtkNew<vtkCallbackCommand> command;
  unsigned long observe(vtkShrinkWrapFilter* wrap)
  {
    this->command->SetClientData(this);
    this->command->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
      auto* once = static_cast<OnceAtFrame*>(data);
      if (!once->done && !once->source->Asked.empty() && once->source->Asked.back() == once->frame)
      {
        once->done = true;
        once->act(static_cast<vtkShrinkWrapFilter*>(caller));
      }
    });
    return wrap->AddObserver(vtkCommand::ProgressEvent, this->command);
  }
};

std::map<vtkIdType, vtkIdType> tracksOf(vtkPolyData* wrap)
{
  std::map<vtkIdType, vtkIdType> tracks; // id -> vertex
  if (auto* ids = vtkIdTypeArray::SafeDownCast(wrap->GetPointData()->GetArray("TrackId")))
  {
    for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
    {
      tracks[ids->GetValue(i)] = i;
    }
  }
  return tracks;
}

void translation()
{
  vtkSmartPointer<testing::SeriesSource> source = movingSphere();
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(source->GetOutputPort());
  wrap->UpdateInformation();
  vtkInformation* out = wrap->GetOutputInformation(0);
  SW_CHECK(wrap->GetFollowsTarget() == 1 &&
      out->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 5 &&
      out->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS())[4] == 4.0,
    "Automatic follows a target with times: the output's times are the target's");

  vtkNew<vtkPolyData> frame2, frame3;
  frame2->DeepCopy(wrapAt(wrap, 2));
  SW_CHECK(source->Asked == std::vector<double>({ 0, 1, 2 }),
    "frame 2 asked the target for frames 0, 1, 2 in order (asked " << source->Asked.size() << ")");
  frame3->DeepCopy(wrapAt(wrap, 3));
  const double edge = wrap->GetChosenEdgeLength();
  std::cout << "frame 3: " << frame3->GetNumberOfPoints() << " vertices, L " << edge << ", "
            << statusOf(frame3) << std::endl;
  SW_CHECK(frame3->GetNumberOfPoints() > 100 && statusOf(frame3) == "ok", "frame 3 wrapped, ok");
  SW_CHECK(fieldValue(frame3, "Time") == 3.0 &&
      frame3->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == 3.0,
    "frame 3 stands at time 3");

  // Every vertex moved by the translation (0.1, 0, 0) since frame 2, and kept its track.
  vtkDataArray* displacement = frame3->GetPointData()->GetArray("Displacement");
  vtkDataArray* velocity = frame3->GetPointData()->GetArray("Velocity");
  SW_CHECK(displacement && velocity, "Displacement and Velocity on the wrap");
  double worst = 0, worstVelocity = 0;
  for (vtkIdType i = 0; displacement && velocity && i < frame3->GetNumberOfPoints(); ++i)
  {
    const double* d = displacement->GetTuple3(i);
    worst = std::max(worst, std::hypot(d[0] - 0.1, d[1], d[2]));
    const double* v = velocity->GetTuple3(i);
    worstVelocity = std::max(worstVelocity, std::hypot(v[0] - 0.1, v[1], v[2]));
  }
  const std::map<vtkIdType, vtkIdType> before = tracksOf(frame2), after = tracksOf(frame3);
  int kept = 0;
  for (const auto& [id, vertex] : after)
  {
    kept += before.count(id);
  }
  std::cout << "largest |Displacement - translation| " << worst << " (" << worst / edge
            << " L), |Velocity - v| " << worstVelocity << "; TrackIds kept " << kept << " of "
            << after.size() << " (frame 2: " << before.size() << ")" << std::endl;
  SW_CHECK(worst <= 0.05 * edge, "Displacement equals the translation within 0.05 L everywhere");
  SW_CHECK(worstVelocity <= 0.05 * edge, "Velocity equals the translation per unit time");
  SW_CHECK(static_cast<vtkIdType>(after.size()) == frame3->GetNumberOfPoints() &&
      kept == static_cast<int>(after.size()) && before.size() == after.size(),
    "every vertex keeps its TrackId (unique ids)");

  // The frame at or before the time asked, as readers give it.
  const struct
  {
    double asked, frame;
  } times[] = { { 2.5, 2 }, { -1, 0 }, { 10, 4 } };
  for (const auto& t : times)
  {
    vtkPolyData* w = wrapAt(wrap, t.asked);
    SW_CHECK(fieldValue(w, "Time") == t.frame &&
        w->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == t.frame,
      "time " << t.asked << " gives frame " << t.frame << " (gave " << fieldValue(w, "Time")
              << ")");
  }
  // Going back: frame 2 from the cache, the target asked for frame 2 alone.
  source->Asked.clear();
  vtkPolyData* again = wrapAt(wrap, 2);
  SW_CHECK(source->Asked == std::vector<double>({ 2 }) &&
      again->GetNumberOfPoints() == frame2->GetNumberOfPoints() &&
      again->GetPoint(7)[0] == frame2->GetPoint(7)[0],
    "going back to frame 2: the cached wrap, the target asked at 2 only");
  // A property edit starts the series over.
  source->Asked.clear();
  wrap->SetSmoothing(wrap->GetSmoothing() * 1.1);
  wrapAt(wrap, 1);
  SW_CHECK(source->Asked == std::vector<double>({ 0, 1 }), "an edit starts the series over");
  // An abort at frame 3 stops the series there; frames 0-2 stay.
  OnceAtFrame abort{ source.Get(), 3, [](vtkShrinkWrapFilter* w) { w->SetAbortExecute(1); } };
  const unsigned long observer = abort.observe(wrap);
  source->Asked.clear();
  vtkPolyData* aborted = wrapAt(wrap, 4);
  wrap->RemoveObserver(observer);
  SW_CHECK(
    aborted->GetNumberOfPoints() == 0 && source->Asked.size() == 2 && source->Asked.back() == 3,
    "an abort at frame 3: an empty output, frame 4 not asked");
  // (An aborted update's empty output stands until the time asked, a property or an input
  // changes, as for an aborted evolution.)
  source->Asked.clear();
  vtkPolyData* resumed = wrapAt(wrap, 3);
  SW_CHECK(resumed->GetNumberOfPoints() > 0 && fieldValue(resumed, "Time") == 3 &&
      std::all_of(source->Asked.begin(), source->Asked.end(), [](double t) { return t == 3; }),
    "asked again: the series resumes at frame 3 (the target still holds it)");
}

// A Distance Field of the moving target (Mesh Signed Distance on the same series) follows too: each
// frame's wrap lands on that frame's field.
void fieldWithTimes()
{
  vtkSmartPointer<testing::SeriesSource> source = movingSphere();
  vtkNew<vtkMeshSignedDistance> field;
  field->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(0, source->GetOutputPort());
  wrap->SetInputConnection(1, field->GetOutputPort());
  double first[6], last[6];
  wrapAt(wrap, 0)->GetBounds(first);
  wrapAt(wrap, 4)->GetBounds(last);
  std::cout << "with a Distance Field: x from " << first[0] << ", " << first[1] << " to " << last[0]
            << ", " << last[1] << std::endl;
  SW_CHECK(std::abs(last[0] - first[0] - 0.4) < 0.01 && std::abs(last[1] - first[1] - 0.4) < 0.01,
    "with a Distance Field that has times, frame 4's wrap stands 0.4 further along x");
}

// A property edited while a series is followed (a script's callback at frame 2): the update stops
// there with a warning, and the next one starts the series over with the new value.
void editDuringSeries()
{
  vtkSmartPointer<testing::SeriesSource> source = movingSphere();
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(source->GetOutputPort());
  OnceAtFrame edit{ source.Get(), 2,
    [](vtkShrinkWrapFilter* w) { w->SetSmoothing(w->GetSmoothing() * 1.1); } };
  const unsigned long observer = edit.observe(wrap);
  vtkPolyData* stopped = wrapAt(wrap, 4);
  wrap->RemoveObserver(observer);
  SW_CHECK(source->Asked == std::vector<double>({ 0, 1, 2 }) && fieldValue(stopped, "Time") == 2,
    "an edit during frame 2: the series stops there (asked " << source->Asked.size() << ")");
  source->Asked.clear();
  wrap->Update(); // the same time asked again: the series starts over, to frame 4
  SW_CHECK(source->Asked == std::vector<double>({ 0, 1, 2, 3, 4 }) &&
      fieldValue(wrap->GetOutput(), "Time") == 4,
    "... and the next update starts it over with the new value (asked " << source->Asked.size()
                                                                        << ")");
}

// Under Cache Memory the frames' outputs are dropped, but the first's and the newest's; a dropped
// frame asked for again is computed again, from the first.
void memoryLimit()
{
  vtkSmartPointer<testing::SeriesSource> source = movingSphere();
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(source->GetOutputPort());
  wrap->SetCacheMemoryMiB(0);
  wrapAt(wrap, 4);
  source->Asked.clear();
  vtkPolyData* kept = wrapAt(wrap, 0);
  SW_CHECK(kept->GetNumberOfPoints() > 0 && source->Asked == std::vector<double>({ 0 }),
    "Cache Memory 0: the first frame stays");
  source->Asked.clear();
  vtkPolyData* again = wrapAt(wrap, 2);
  // (Frame 0's data is the source's output still: only frames 1 and 2 make it run.)
  SW_CHECK(again->GetNumberOfPoints() > 0 && fieldValue(again, "Time") == 2 &&
      source->Asked == std::vector<double>({ 1, 2 }),
    "Cache Memory 0: frame 2, dropped, is computed again from the first (asked "
      << source->Asked.size() << " frames)");
}

void staticAndEvolutionSteps()
{
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(sphere->GetOutputPort());
  wrap->UpdateInformation();
  vtkInformation* out = wrap->GetOutputInformation(0);
  SW_CHECK(wrap->GetFollowsTarget() == 0 &&
      out->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == wrap->GetNumberOfSteps() + 1,
    "a static target: its evolution's steps are the times");
  // Follow Target Time on a static target: one frame, no times, the landed wrap with its tracks.
  wrap->SetTimeMode(vtkShrinkWrapFilter::TIME_FOLLOW_TARGET);
  wrap->Update();
  SW_CHECK(wrap->GetFollowsTarget() == 1 &&
      !out->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) &&
      wrap->GetOutput()->GetNumberOfPoints() > 100 &&
      wrap->GetOutput()->GetPointData()->GetArray("TrackId") != nullptr,
    "Follow Target Time on a static target: one frame, no time steps, a wrap with TrackIds");
  wrap->SetTimeMode(vtkShrinkWrapFilter::TIME_AUTOMATIC);
  vtkSmartPointer<testing::SeriesSource> source = movingSphere();
  wrap->SetInputConnection(source->GetOutputPort());
  wrap->SetTimeMode(vtkShrinkWrapFilter::TIME_EVOLUTION_STEPS);
  wrap->UpdateInformation();
  SW_CHECK(wrap->GetFollowsTarget() == 0 &&
      out->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == wrap->GetNumberOfSteps() + 1,
    "Evolution Steps on a moving target: the steps are the times");
  wrapAt(wrap, 2);
  SW_CHECK(source->Asked.size() == 1, "... and the target is read once");
}
} // namespace

int TestFollowTargetTime(int, char*[])
{
  translation();
  fieldWithTimes();
  editDuringSeries();
  memoryLimit();
  staticAndEvolutionSteps();
  return testing::finish("TestFollowTargetTime");
}
