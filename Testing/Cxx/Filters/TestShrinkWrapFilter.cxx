// vtkShrinkWrapFilter through a VTK pipeline: time steps, the step cache, the output's arrays, a
// closed one-piece result, the DistanceField and InitialSurface ports, bad input, and a surface
// split between steps against the same surface given as InitialSurface.
#include "Distance/SignedDistance.h"
#include "Remeshing/EdgeSplits.h"
#include "Surface/Icosphere.h"
#include "Surface/SurfaceMesh.h"
#include "TestUtilities.h"
#include "Wrap/AutomaticSizes.h"
#include "Wrap/Wrap.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkClipPolyData.h>
#include <vtkCommand.h>
#include <vtkInformation.h>
#include <vtkPlane.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkReverseSense.h>
#include <vtkSphereSource.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkSuperquadricSource.h>
#include <vtkTriangleFilter.h>

#include <functional>

namespace
{
vtkSmartPointer<vtkPolyData> target(double y = 0.7, double z = 0.5)
{
  vtkNew<vtkSuperquadricSource> source; // a rounded box, a little concave at its faces
  source->SetScale(1.0, y, z);
  source->SetThetaRoundness(0.3);
  source->SetPhiRoundness(0.3);
  source->SetThetaResolution(32);
  source->SetPhiResolution(32);
  source->ToroidalOff();
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

std::vector<double> pointsOf(vtkPolyData* mesh)
{
  std::vector<double> p;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    p.insert(p.end(), x, x + 3);
  }
  return p;
}

// The surface: its points and its triangles' point ids (edge flips change the latter from step to
// step).
std::vector<double> surfaceOf(vtkPolyData* mesh)
{
  std::vector<double> s = pointsOf(mesh);
  for (const auto& t : testing::triangulated(mesh).triangles)
  {
    s.insert(s.end(), t.begin(), t.end());
  }
  return s;
}

int stepOf(vtkPolyData* mesh)
{
  vtkDataArray* a = mesh->GetFieldData()->GetArray("StepIndex");
  return a ? static_cast<int>(a->GetTuple1(0)) : -1;
}

std::string statusOf(vtkPolyData* mesh)
{
  auto* a = vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("Status"));
  return a ? a->GetValue(0) : std::string();
}

int errorsWhile(vtkAlgorithm* filter, const std::function<void()>& run)
{
  struct Counter
  {
    int errors = 0;
  } counter;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&counter);
  observer->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++static_cast<Counter*>(data)->errors; });
  const unsigned long id = filter->AddObserver(vtkCommand::ErrorEvent, observer);
  run();
  filter->RemoveObserver(id);
  return counter.errors;
}

// A plain update: the last step, a closed one-piece surface with its arrays, near the target.
void lastStep(vtkShrinkWrapFilter* wrap, vtkPolyData* box)
{
  wrap->SetNumberOfSteps(60);
  wrap->SetResolution(64);
  wrap->UpdateInformation();
  vtkInformation* info = wrap->GetOutputInformation(0);
  const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  SW_CHECK(n == 61, "TIME_STEPS has N_t + 1 entries (" << n << ")");
  SW_CHECK(info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE())[1] == 60 * 0.015,
    "TIME_RANGE ends at N_t tau");

  // No time asked: the last step.
  wrap->Update();
  vtkPolyData* out = wrap->GetOutput();
  SW_CHECK(stepOf(out) == 60 && statusOf(out) == "ok", "a plain update gives the last step, ok");
  SW_CHECK(wrap->GetNumberOfComputedSteps() == 60, "60 steps computed");
  shrinkwrap::SurfaceMesh closed;
  std::string error;
  std::vector<shrinkwrap::Vec3> x(out->GetNumberOfPoints());
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    out->GetPoint(i, x[i].data());
  }
  SW_CHECK(testing::builds(x, testing::triangulated(out).triangles, closed, error),
    "the output is a closed 2-manifold: " << error);
  vtkNew<vtkPolyDataConnectivityFilter> pieces;
  pieces->SetInputData(out);
  pieces->SetExtractionModeToAllRegions();
  pieces->Update();
  SW_CHECK(pieces->GetNumberOfExtractedRegions() == 1, "one component");
  for (const char* name :
    { "Distance", "AdvectionAlignment", "MeanCurvature", "CoVolume", "TangentialVelocity" })
  {
    SW_CHECK(out->GetPointData()->GetArray(name) &&
        out->GetPointData()->GetArray(name)->GetNumberOfTuples() == out->GetNumberOfPoints(),
      "point array " << name);
  }
  SW_CHECK(out->GetPointData()->GetNormals() != nullptr, "point normals");
  for (const char* name : { "MinAngle", "MaxAngle", "JacobianCondition" })
  {
    SW_CHECK(out->GetCellData()->GetArray(name) &&
        out->GetCellData()->GetArray(name)->GetNumberOfTuples() == out->GetNumberOfCells(),
      "cell array " << name);
  }
  // The wrap approaches the target: most vertices within a couple of cells of it.
  vtkDataArray* distance = out->GetPointData()->GetArray("Distance");
  std::vector<double> d;
  for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
  {
    d.push_back(std::abs(distance->GetTuple1(i)));
  }
  std::sort(d.begin(), d.end());
  const double h = testing::fieldCell(out);
  std::printf("after 60 steps: median |d| = %.3f h, 90th percentile %.3f h\n", d[d.size() / 2] / h,
    d[d.size() * 9 / 10] / h);
  SW_CHECK(d[d.size() / 2] < 2 * h, "the surface approaches the target");
}

// Going back in time and snapping; returns step 30 of `wrap`.
std::vector<double> stepsAndCache(vtkShrinkWrapFilter* wrap, vtkPolyData* box)
{
  // A step in the middle: exactly that step, and the same surface as a fresh run stopped there.
  wrap->UpdateTimeStep(30 * 0.015);
  const std::vector<double> middle = surfaceOf(wrap->GetOutput());
  SW_CHECK(stepOf(wrap->GetOutput()) == 30, "time 30 tau gives step 30");
  SW_CHECK(wrap->GetNumberOfComputedSteps() == 60, "going back computes nothing");
  vtkNew<vtkShrinkWrapFilter> fresh;
  fresh->SetInputData(box);
  fresh->SetResolution(64);
  fresh->SetNumberOfSteps(30);
  fresh->Update();
  SW_CHECK(
    surfaceOf(fresh->GetOutput()) == middle, "the same surface as a fresh run stopped at step 30");

  wrap->UpdateTimeStep(17.4 * 0.015);
  SW_CHECK(stepOf(wrap->GetOutput()) == 17, "times snap to the nearest step");

  // A parameter change drops the cache.
  wrap->SetAdvectionSpeed(2.0);
  wrap->UpdateTimeStep(10 * 0.015);
  SW_CHECK(wrap->GetNumberOfComputedSteps() == 10,
    "changing C drops the cache (" << wrap->GetNumberOfComputedSteps() << ")");
  wrap->SetAdvectionSpeed(1.0);

  // A parameter change drops the cache.
  wrap->SetAdvectionSpeed(2.0);
  wrap->UpdateTimeStep(10 * 0.015);
  SW_CHECK(wrap->GetNumberOfComputedSteps() == 10,
    "changing C drops the cache (" << wrap->GetNumberOfComputedSteps() << ")");
  wrap->SetAdvectionSpeed(1.0);
  return middle;
}

void cacheWithFlips()
{
  // Edge flips (on by default) on a slender target: the triangles change from step to step. A cache
  // over its memory limit keeps every k-th step; a dropped step is recomputed from the nearest kept
  // one, with that step's triangles, and comes out the same as a fresh run.
  vtkSmartPointer<vtkPolyData> slender = target(0.15, 0.15); // flips from about step 70
  auto wrapOf = [&](int steps, double cacheLimit) {
    vtkNew<vtkShrinkWrapFilter> filter;
    filter->SetInputData(slender);
    filter->SetResolution(64);
    filter->SetNumberOfSteps(steps);
    filter->SetCacheMemoryMiB(cacheLimit);
    filter->Update();
    return vtkSmartPointer<vtkShrinkWrapFilter>(filter.Get());
  };
  auto thin = wrapOf(100, 0.5); // MiB: about ten steps of 642 vertices
  const auto lastTriangles = testing::triangulated(thin->GetOutput()).triangles;
  const vtkIdType lastCount = thin->GetOutput()->GetNumberOfPoints();
  thin->UpdateTimeStep(0);
  SW_CHECK(testing::triangulated(thin->GetOutput()).triangles != lastTriangles,
    "edges flipped during the evolution");
  // Remeshing (the default) changes the vertex count too: the cache keeps each step's own
  // triangles.
  SW_CHECK(thin->GetOutput()->GetNumberOfPoints() != lastCount,
    "the vertex count changed during the evolution ("
      << thin->GetOutput()->GetNumberOfPoints() << " at step 0, " << lastCount << " at step 100)");
  thin->UpdateTimeStep(93 * 0.015);
  const int recomputed = thin->GetNumberOfComputedSteps() - 100;
  std::printf("step 93 with a 0.5 MiB cache: %d steps recomputed\n", recomputed);
  SW_CHECK(recomputed > 0 && recomputed < 93,
    "a dropped step resumes from a kept one (" << recomputed << " steps)");
  SW_CHECK(stepOf(thin->GetOutput()) == 93 &&
      surfaceOf(thin->GetOutput()) == surfaceOf(wrapOf(93, 512)->GetOutput()),
    "and gives the same surface as a fresh run");
}

void editsAndAbortsWhileRunning(vtkPolyData* box)
{
  // While it runs: a property set from a progress callback applies from the next update; an abort
  // keeps the computed steps, and the next request for another time resumes from them.
  {
    vtkNew<vtkShrinkWrapFilter> running;
    running->SetInputData(box);
    running->SetResolution(64);
    running->SetNumberOfSteps(40);
    struct Plan
    {
      int events = 0, editAt = 0, abortAt = 0;
    } plan;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&plan);
    onProgress->SetCallback([](vtkObject* caller, unsigned long, void* data, void*) {
      auto* p = static_cast<Plan*>(data);
      auto* filter = static_cast<vtkShrinkWrapFilter*>(caller);
      ++p->events;
      if (p->events == p->editAt)
      {
        filter->SetAngleWeight(0.6);
      }
      if (p->events == p->abortAt)
      {
        filter->AbortExecuteOn();
      }
    });
    running->AddObserver(vtkCommand::ProgressEvent, onProgress);
    plan.editAt = 10;
    running->UpdateTimeStep(40 * 0.015);
    SW_CHECK(running->GetNumberOfComputedSteps() == 40 && stepOf(running->GetOutput()) == 40,
      "a property set during the run: the run ends");
    const std::vector<double> withOldValue = surfaceOf(running->GetOutput());
    running->UpdateTimeStep(40 * 0.015);
    SW_CHECK(
      running->GetNumberOfComputedSteps() == 40 && surfaceOf(running->GetOutput()) != withOldValue,
      "the same request runs again, from step 0, with the new value");
    plan = { 0, 0, 15 };
    running->SetAngleWeight(0.5);
    running->UpdateTimeStep(40 * 0.015);
    SW_CHECK(
      running->GetOutput()->GetNumberOfPoints() == 0 && running->GetNumberOfComputedSteps() < 40,
      "an abort: an empty output");
    const int before = running->GetNumberOfComputedSteps();
    running->UpdateTimeStep(40 * 0.015);
    SW_CHECK(running->GetOutput()->GetNumberOfPoints() == 0 &&
        running->GetNumberOfComputedSteps() == before,
      "the same request after an abort does not run again by itself");
    running->UpdateTimeStep(39 * 0.015);
    SW_CHECK(stepOf(running->GetOutput()) == 39 && running->GetNumberOfComputedSteps() == 39 &&
        before < 39,
      "another time resumes from step " << before);
  }
}

void distanceFieldPort(vtkPolyData* box, const std::vector<double>& middle)
{
  // The DistanceField port: the same field from Mesh Signed Distance (on the lattice the filter
  // places for the offset start) gives the same wrap.
  vtkNew<vtkMeshSignedDistance> sdf;
  sdf->SetInputData(box);
  sdf->SetResolution(64);
  shrinkwrap::WrapSettings settings;
  settings.resolution = 64;
  const shrinkwrap::Box bounds = shrinkwrap::convert::boundsOf(box);
  const double gap = shrinkwrap::gapSizeFor(settings, bounds);
  sdf->SetOffsetFactor(shrinkwrap::fieldPlacement(settings, gap, bounds, false).offsetFactor);
  vtkNew<vtkShrinkWrapFilter> withField;
  withField->SetInputData(box);
  withField->SetDistanceFieldConnection(sdf->GetOutputPort());
  withField->SetNumberOfSteps(30);
  withField->Update();
  SW_CHECK(
    surfaceOf(withField->GetOutput()) == middle, "a DistanceField input gives the same wrap");
}

// Bad input: an error and an empty output, or a warning; never a crash. Then the InitialSurface
// port and the offset start on the same filter.
void badInputAndStarts(vtkPolyData* box)
{
  // Bad input: an error and an empty output, or a warning; never a crash.
  vtkNew<vtkShrinkWrapFilter> bad;
  bad->SetStartingShape(
    vtkShrinkWrapFilter::ICOSPHERE); // the paper's scheme: 642 vertices throughout
  bad->SetRemeshing(false);
  vtkNew<vtkPolyData> empty;
  bad->SetInputData(empty);
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0 && bad->GetOutput()->GetNumberOfPoints() == 0,
    "a target without polygons: error, empty output");
  vtkNew<vtkPolyData> nanBox;
  nanBox->DeepCopy(box);
  nanBox->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  bad->SetInputData(nanBox);
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0 && bad->GetOutput()->GetNumberOfPoints() == 0,
    "NaN coordinates: error, empty output");
  bad->SetInputData(box);
  bad->SetResolution(32);
  bad->SetTimePerStep(0);
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0 && bad->GetOutput()->GetNumberOfPoints() == 0,
    "tau = 0: error");
  bad->SetTimePerStep(-1);
  SW_CHECK(errorsWhile(bad, [&] { bad->Update(); }) > 0, "tau < 0: error");
  bad->SetTimePerStep(0.015);
  bad->SetNumberOfSteps(0);
  bad->Update();
  SW_CHECK(stepOf(bad->GetOutput()) == 0 && bad->GetOutput()->GetNumberOfPoints() == 642,
    "N_t = 0: the starting surface");
  bad->SetNumberOfSteps(5);
  vtkNew<vtkImageData> noArray;
  noArray->SetDimensions(4, 4, 4);
  bad->SetInputData(1, noArray);
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0, "a DistanceField without SignedDistance: error");
  vtkNew<vtkMeshSignedDistance> tight;
  tight->SetInputData(box);
  tight->SetResolution(16);
  tight->SetOffsetFactor(0);
  bad->SetDistanceFieldConnection(tight->GetOutputPort());
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0, "a field that does not contain the start: error");
  bad->SetInputConnection(1, nullptr);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(2.0);
  vtkNew<vtkPlane> plane;
  plane->SetNormal(0, 0, 1);
  vtkNew<vtkClipPolyData> open;
  open->SetInputConnection(sphere->GetOutputPort());
  open->SetClipFunction(plane);
  bad->SetInitialSurfaceConnection(open->GetOutputPort());
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0 && bad->GetOutput()->GetNumberOfPoints() == 0,
    "an open initial surface: error");
  sphere->SetRadius(1.0); // inside the field, around the target
  bad->SetInitialSurfaceConnection(sphere->GetOutputPort());
  bad->Update();
  // Five steps from it do not land on the box: the status says so, not "failed".
  SW_CHECK(stepOf(bad->GetOutput()) == 5 &&
      (statusOf(bad->GetOutput()) == "ok" ||
        statusOf(bad->GetOutput()).rfind("not landed", 0) == 0),
    "a closed initial surface wraps (" << statusOf(bad->GetOutput()) << ")");

  // The same sphere facing inwards is turned outwards: with D > 0 (not symmetric in N) it wraps the
  // same.
  bad->SetConcavityPush(0.5);
  bad->Update();
  const std::vector<double> outwards = pointsOf(bad->GetOutput());
  vtkNew<vtkReverseSense> inwards;
  inwards->SetInputConnection(sphere->GetOutputPort());
  bad->SetInitialSurfaceConnection(inwards->GetOutputPort());
  bad->Update();
  const std::vector<double> turned = pointsOf(bad->GetOutput());
  double largest = outwards.size() == turned.size() ? 0 : 1e9;
  for (size_t i = 0; i < turned.size() && i < outwards.size(); ++i)
  {
    largest = std::max(largest, std::abs(turned[i] - outwards[i]));
  }
  SW_CHECK(largest < 1e-9,
    "an inward-facing initial surface wraps like the outward one (" << largest << ")");

  // The offset start asked to reach beyond the field: an error and an empty output; a sane one
  // wraps.
  bad->SetInitialSurfaceConnection(nullptr);
  bad->SetConcavityPush(0);
  bad->SetStartingShape(vtkShrinkWrapFilter::OFFSET_SURFACE);
  bad->SetStartOffsetInCells(1000);
  bad->SetGapSize(1000); // the offset is at most 0.4 of the gap
  SW_CHECK(
    errorsWhile(bad, [&] { bad->Update(); }) > 0 && bad->GetOutput()->GetNumberOfPoints() == 0,
    "an offset surface beyond the distance field: error");
  bad->SetStartOffsetInCells(3);
  bad->SetGapSize(0);
  bad->Update();
  SW_CHECK(statusOf(bad->GetOutput()) == "ok" && bad->GetOutput()->GetNumberOfPoints() > 0,
    "then a sane offset wraps");
}

// Issue #9: a surface split edge by edge in the core, given as InitialSurface with Initial
// Relaxation 0, evolves as the core evolves the unsplit surface split between steps (TestEvolver
// shows the same on the core alone; here the filter's way in is the reference).
void splitSurfaceAsInitialSurface(vtkPolyData* box)
{
  using namespace shrinkwrap;
  const TriangleSoup sphere = icosphere(2, convert::boundsOf(box).center(), 1.2);
  SurfaceMesh split = testing::meshOf(sphere);
  splitEdges(split, edgesOf(split));
  vtkNew<vtkPolyData> given;
  convert::setTriangles(split.points(), split.triangles(), given);
  const int steps = 20;
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(box);
  wrap->SetInputData(2, given);
  wrap->SetInitialRelaxation(0);
  wrap->SetRemeshing(false);
  wrap->SetResolution(48);
  wrap->SetSolverTolerance(1e-12);
  wrap->SetNumberOfSteps(steps);
  wrap->Update();

  // The core, as the filter runs it, from the unsplit icosphere split between steps.
  WrapSettings settings; // without remeshing: the edit path, not the remeshing, is under test
  settings.remeshing = false;
  settings.resolution = 48;
  settings.evolution.solverTolerance = 1e-12;
  convert::SoupCounts counts;
  WrapTarget target;
  SW_CHECK(makeTarget(convert::soupOf({ box }, counts), {}, target), "the target");
  target.givenStart = true;
  WrapPlan plan;
  SW_CHECK(planWrap(target, settings, plan), "the plan");
  Notes notes;
  WrapFields fields;
  SW_CHECK(makeWrapFields(target, plan, {}, notes, fields), "the wrap's fields");
  std::unique_ptr<WrapSession> session;
  SW_CHECK(WrapSession::create(fields, plan, testing::meshOf(sphere), session), "a session");
  if (!session)
  {
    return;
  }
  session->edit([](SurfaceMesh& mesh) { splitEdges(mesh, edgesOf(mesh)); });
  session->advanceTo(steps);
  const std::vector<Vec3> x = session->surface(steps).points;
  vtkPolyData* out = wrap->GetOutput();
  double largest = static_cast<vtkIdType>(x.size()) == out->GetNumberOfPoints() ? 0 : INFINITY;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints() && i < static_cast<vtkIdType>(x.size()); ++i)
  {
    Vec3 p;
    out->GetPoint(i, p.data());
    largest = std::max(largest, (p - x[i]).norm());
  }
  std::printf("split between steps against the split surface as InitialSurface, %d steps: largest "
              "difference %.3g (target size 2)\n",
    steps, largest);
  SW_CHECK(largest < 1e-8, "the filter's InitialSurface path equals the edit");
}

} // namespace

int TestShrinkWrapFilter(int, char*[])
{
  vtkSmartPointer<vtkPolyData> box = target();
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(box);
  lastStep(wrap, box);
  const std::vector<double> middle = stepsAndCache(wrap, box);
  cacheWithFlips();
  editsAndAbortsWhileRunning(box);
  distanceFieldPort(box, middle);
  badInputAndStarts(box);
  splitSurfaceAsInitialSurface(box);
  return testing::finish("TestShrinkWrapFilter");
}
