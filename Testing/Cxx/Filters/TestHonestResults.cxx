// Inputs that used to give a wrong result reported "ok": a target whose triangles all face inwards,
// a closed mesh written double-sided (every triangle in both orientations), and a run that has
// not landed, a target far from the origin, sand (many parts too small to wrap). Each now wraps
// right or says why. And a long setup (the field, the gap closing, the start) reports progress and
// stops at an abort.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCellLocator.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkReverseSense.h>
#include <vtkSelectEnclosedPoints.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace testing;

constexpr double kRadius = 0.5;

vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(kRadius);
  source->SetThetaResolution(48);
  source->SetPhiResolution(48);
  source->Update();
  return source->GetOutput();
}

std::string statusOf(vtkPolyData* wrap)
{
  auto* a = vtkStringArray::SafeDownCast(wrap->GetFieldData()->GetAbstractArray("Status"));
  return a ? a->GetValue(0) : "";
}

// The wrap at its last step, and what the filter warned of.
vtkSmartPointer<vtkPolyData> wrapped(vtkShrinkWrapFilter* wrap, std::string& warnings)
{
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&warnings);
  observer->SetCallback([](vtkObject*, unsigned long, void* said, void* message) {
    *static_cast<std::string*>(said) += static_cast<const char*>(message);
  });
  wrap->AddObserver(vtkCommand::WarningEvent, observer);
  wrap->AddObserver(vtkCommand::ErrorEvent, observer);
  wrap->UpdateTimeStep(1e30);
  wrap->RemoveObserver(observer);
  return wrap->GetOutput();
}

// The share of the wrap's vertices inside `outward` (a closed mesh facing out): behind the facet
// closest to them by more than 1e-6 of its size.
double insideShare(vtkPolyData* wrap, vtkPolyData* outward)
{
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(outward);
  locator->BuildLocator();
  int inside = 0;
  for (vtkIdType i = 0; i < wrap->GetNumberOfPoints(); ++i)
  {
    double x[3], c[3], n[3], d2;
    vtkIdType cell;
    int sub;
    wrap->GetPoint(i, x);
    locator->FindClosestPoint(x, c, cell, sub, d2);
    vtkCell* facet = outward->GetCell(cell);
    vtkPolygon::ComputeNormal(facet->GetPoints(), n);
    inside += (x[0] - c[0]) * n[0] + (x[1] - c[1]) * n[1] + (x[2] - c[2]) * n[2] < -1e-6 * kRadius;
  }
  return wrap->GetNumberOfPoints() > 0 ? static_cast<double>(inside) / wrap->GetNumberOfPoints()
                                       : 1.0;
}

// A closed sphere with every triangle reversed: the field signs it by its inside all the same, and
// the wrap lands outside it, as on the sphere itself.
void inwardFacingTarget()
{
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(sphere());
  reverse->ReverseCellsOn();
  reverse->ReverseNormalsOn();
  reverse->Update();
  for (const bool reversed : { false, true })
  {
    vtkNew<vtkShrinkWrapFilter> wrap;
    wrap->SetInputData(reversed ? reverse->GetOutput() : sphere().Get());
    std::string warnings;
    vtkPolyData* out = wrapped(wrap, warnings);
    const double inside = insideShare(out, sphere());
    std::cout << (reversed ? "reversed" : "as given") << ": " << out->GetNumberOfPoints()
              << " vertices, " << 100 * inside << "% inside the sphere, status " << statusOf(out)
              << std::endl;
    SW_CHECK(out->GetNumberOfPoints() > 0 && statusOf(out) == "ok",
      (reversed ? "reversed" : "as given") << ": a wrap, ok");
    SW_CHECK(inside < 0.01,
      (reversed ? "reversed" : "as given")
        << ": under 1% of the vertices inside the sphere (" << 100 * inside << "%)");
  }
}

// Every triangle twice, once each way (as some exporters write closed meshes): the field is signed
// (inside negative), and the wrap lands as on the mesh written once.
void doubleSidedTarget()
{
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(sphere());
  reverse->ReverseCellsOn();
  vtkNew<vtkAppendPolyData> both;
  both->AddInputData(sphere());
  both->AddInputConnection(reverse->GetOutputPort());
  both->Update();
  vtkNew<vtkMeshSignedDistance> field;
  field->SetInputConnection(both->GetOutputPort());
  field->SetResolution(40);
  field->Update();
  vtkImageData* image = field->GetOutput();
  const double isSigned = image->GetFieldData()->GetArray("Signed")->GetTuple1(0);
  const double range0 = image->GetPointData()->GetArray("SignedDistance")->GetRange()[0];
  std::cout << "double-sided: Signed " << isSigned << ", smallest distance " << range0 << std::endl;
  SW_CHECK(isSigned == 1 && std::abs(range0 + kRadius) < 0.02,
    "double-sided: the field is signed, -" << kRadius << " at the centre (" << range0 << ")");

  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputConnection(both->GetOutputPort());
  std::string warnings;
  vtkPolyData* out = wrapped(wrap, warnings);
  const double inside = insideShare(out, sphere());
  SW_CHECK(
    out->GetNumberOfPoints() > 0 && statusOf(out) == "ok" && warnings.empty() && inside < 0.01,
    "double-sided: the wrap lands outside the sphere, ok, no warning (" << statusOf(out) << "; "
                                                                        << warnings << ")");
}

// Too few steps from a far start: the last step says it has not landed, and a warning says what to
// change; a run that lands says ok.
void notLanded()
{
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(sphere());
  wrap->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
  wrap->SetRemeshing(false);
  wrap->SetNumberOfSteps(2);
  std::string warnings;
  vtkPolyData* out = wrapped(wrap, warnings);
  std::cout << "2 steps from an icosphere: " << statusOf(out) << " | " << warnings << std::endl;
  SW_CHECK(statusOf(out).rfind("not landed: 95% of its vertices lie within", 0) == 0 &&
      warnings.find("has not landed on the target after its 2 steps") != std::string::npos &&
      warnings.find("raise Number Of Steps") != std::string::npos,
    "2 steps: not landed, in Status and a warning");
  wrap->SetNumberOfSteps(200);
  warnings.clear();
  out = wrapped(wrap, warnings);
  SW_CHECK(statusOf(out) == "ok" && warnings.empty(),
    "200 steps: ok (" << statusOf(out) << "; " << warnings << ")");
}

// Sand: 10,000 disjoint tetrahedra 0.005 across in a unit cube, far smaller than the default edges.
// Grains closer than the Gap Size are bridged; the others cannot be wrapped alone. The run neither
// fails (a grain's part of the wrap shrinks to nothing and goes) nor says "ok" while grains lie
// outside the wrap: Status and a warning count the parts left out, as the test counts them (grains
// not enclosed by the wrap, farther than 2 cells from it).
void sand()
{
  constexpr int kGrains = 10000;
  constexpr double kSize = 0.005;
  const double corners[4][3] = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  const vtkIdType faces[4][3] = { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } };
  for (unsigned draw : { 1u, 2u })
  {
    std::mt19937 random(draw);
    std::uniform_real_distribution<double> uniform(-0.5, 0.5);
    vtkNew<vtkPoints> points, centers;
    vtkNew<vtkCellArray> triangles;
    for (int g = 0; g < kGrains; ++g)
    {
      const double c[3] = { uniform(random), uniform(random), uniform(random) };
      centers->InsertNextPoint(c);
      const vtkIdType first = points->GetNumberOfPoints();
      for (const auto& k : corners)
      {
        points->InsertNextPoint(
          c[0] + k[0] * kSize / 2, c[1] + k[1] * kSize / 2, c[2] + k[2] * kSize / 2);
      }
      for (const auto& f : faces)
      {
        const vtkIdType ids[3] = { first + f[0], first + f[1], first + f[2] };
        triangles->InsertNextCell(3, ids);
      }
    }
    vtkNew<vtkPolyData> target;
    target->SetPoints(points);
    target->SetPolys(triangles);
    vtkNew<vtkShrinkWrapFilter> wrap;
    wrap->SetInputData(target);
    std::string warnings;
    vtkPolyData* out = wrapped(wrap, warnings);
    const std::string status = statusOf(out);

    vtkNew<vtkPolyData> grains;
    grains->SetPoints(centers);
    vtkNew<vtkSelectEnclosedPoints> enclosed;
    enclosed->SetInputData(grains);
    enclosed->SetSurfaceData(out);
    enclosed->Update();
    vtkNew<vtkCellLocator> locator;
    locator->SetDataSet(out);
    locator->BuildLocator();
    const double cell = out->GetFieldData()->GetArray("FieldCellSize")->GetComponent(0, 0);
    int surely = 0, maybe = 0; // outside by more than 2 cells and the grain's size; 2 cells
    for (vtkIdType g = 0; g < kGrains && out->GetNumberOfPoints() > 0; ++g)
    {
      double x[3], c[3], d2;
      vtkIdType id;
      int sub;
      centers->GetPoint(g, x);
      locator->FindClosestPoint(x, c, id, sub, d2);
      const bool outside = !enclosed->IsInside(g);
      surely += outside && std::sqrt(d2) > 2 * cell + kSize;
      maybe += outside && std::sqrt(d2) > 2 * cell - kSize;
    }
    vtkDataArray* counted = out->GetFieldData()->GetArray("LeftOutParts");
    const double left = counted ? counted->GetComponent(0, 0) : -1;
    std::cout << "sand, draw " << draw << ": " << status << "; " << surely << " to " << maybe
              << " grains outside the wrap by more than 2 cells" << std::endl;
    SW_CHECK(out->GetNumberOfPoints() > 0 && status.rfind("left out: ", 0) == 0 &&
        warnings.find("Left out ") != std::string::npos && left >= surely && left <= maybe &&
        counted->GetComponent(0, 1) == kGrains,
      "sand, draw " << draw << ": the parts left out said (" << status << "; LeftOutParts " << left
                    << ", grains outside " << surely << " to " << maybe << ")");
  }
}

// The sphere in UTM-like coordinates (double points): the same wrap as at the origin, moved.
void farFromOrigin()
{
  const double centre[3] = { 500000, 5000000, 100 };
  vtkSmartPointer<vtkPolyData> near = sphere();
  auto far = vtkSmartPointer<vtkPolyData>::New();
  far->DeepCopy(near);
  vtkNew<vtkPoints> moved;
  moved->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < near->GetNumberOfPoints(); ++i)
  {
    double p[3];
    near->GetPoint(i, p);
    moved->InsertNextPoint(p[0] + centre[0], p[1] + centre[1], p[2] + centre[2]);
  }
  far->SetPoints(moved);
  vtkNew<vtkShrinkWrapFilter> atOrigin, there;
  atOrigin->SetInputData(near);
  there->SetInputData(far);
  std::string warnings;
  vtkPolyData* a = wrapped(atOrigin, warnings);
  vtkPolyData* b = wrapped(there, warnings);
  double largest = 0; // the farther wrap's vertices from the sphere's surface
  for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
  {
    double p[3];
    b->GetPoint(i, p);
    const double r = std::sqrt((p[0] - centre[0]) * (p[0] - centre[0]) +
      (p[1] - centre[1]) * (p[1] - centre[1]) + (p[2] - centre[2]) * (p[2] - centre[2]));
    largest = std::max(largest, std::abs(r - kRadius));
  }
  std::cout << "far from the origin: " << b->GetNumberOfPoints() << " vertices ("
            << a->GetNumberOfPoints() << " at the origin), " << statusOf(b) << ", largest |r - R| "
            << largest << std::endl;
  SW_CHECK(statusOf(b) == "ok" &&
      std::abs(b->GetNumberOfPoints() - a->GetNumberOfPoints()) <= 0.02 * a->GetNumberOfPoints() &&
      largest < 0.1 * fieldCell(b),
    "far from the origin: ok, the origin's vertex count within 2%, on the sphere within 0.1 cells");
}

// A setup of seconds (a fine wrap: its field, closing, and a start coarsened to a short L):
// progress events before the first step, rising; an abort at the first one ends the setup with a
// warning and an empty output, and the next update wraps.
void abortInSetup()
{
  struct Seen
  {
    std::vector<double> fractions;
    bool abortFirst = true;
  } seen;
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(sphere());
  wrap->SetResolution(160);
  wrap->SetTargetEdgeLength(0.012);
  wrap->SetNumberOfSteps(2);
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&seen);
  onProgress->SetCallback([](vtkObject* caller, unsigned long, void* data, void* amount) {
    auto* s = static_cast<Seen*>(data);
    s->fractions.push_back(*static_cast<double*>(amount));
    if (s->abortFirst)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      s->abortFirst = false;
    }
  });
  wrap->AddObserver(vtkCommand::ProgressEvent, onProgress);
  std::string warnings;
  vtkPolyData* out = wrapped(wrap, warnings);
  std::cout << "aborted at the first progress event (" << seen.fractions.size()
            << " events): " << warnings << std::endl;
  SW_CHECK(
    out->GetNumberOfPoints() == 0 && warnings.find("aborted while it set up") != std::string::npos,
    "an abort during the setup: an empty output and a warning");
  seen.fractions.clear();
  wrap->Modified();
  warnings.clear();
  out = wrapped(wrap, warnings);
  int setup = 0;
  bool rising = true;
  for (std::size_t k = 0; k < seen.fractions.size(); ++k)
  {
    setup += seen.fractions[k] > 0 && seen.fractions[k] < vtkShrinkWrapFilter::kSetupShare;
    rising = rising && (k == 0 || seen.fractions[k] >= seen.fractions[k - 1]);
  }
  std::cout << "then " << out->GetNumberOfPoints() << " vertices, " << seen.fractions.size()
            << " progress events, " << setup << " in the setup:";
  for (double f : seen.fractions)
  {
    std::cout << " " << f;
  }
  std::cout << std::endl;
  SW_CHECK(out->GetNumberOfPoints() > 0 && setup >= 10 && rising,
    "then the wrap, with at least 10 rising progress events in its setup (" << setup << ")");

  // Stopped within its second step (at the first progress event inside it, between its phases):
  // an empty output; the next update resumes from the first step's cache and gives the wrap of a
  // run never stopped, to 1e-6 of its size.
  vtkNew<vtkPoints> whole;
  whole->DeepCopy(out->GetPoints());
  wrap->SetNumberOfSteps(3);
  wrap->UpdateTimeStep(1e30);
  whole->DeepCopy(wrap->GetOutput()->GetPoints());
  wrap->Modified();
  vtkNew<vtkCallbackCommand> inStep;
  struct Within
  {
    bool stopped = false;
  } within;
  inStep->SetClientData(&within);
  inStep->SetCallback([](vtkObject* caller, unsigned long, void* data, void* amount) {
    auto* w = static_cast<Within*>(data);
    const double p = *static_cast<double*>(amount);
    // (step - 0.5) / 3 of the steps' share: the middle of step 2
    const double middle =
      vtkShrinkWrapFilter::kSetupShare + (1 - vtkShrinkWrapFilter::kSetupShare) * 1.5 / 3;
    if (!w->stopped && std::abs(p - middle) < 1e-9)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
      w->stopped = true;
    }
  });
  wrap->RemoveAllObservers();
  wrap->AddObserver(vtkCommand::ProgressEvent, inStep);
  warnings.clear();
  out = wrapped(wrap, warnings);
  const int computed = wrap->GetNumberOfComputedSteps();
  SW_CHECK(within.stopped && out->GetNumberOfPoints() == 0 && computed == 1,
    "stopped within step 2: an empty output, 1 step computed (" << computed << ")");
  wrap->UpdateTimeStep(3 * wrap->GetTimePerStep()); // another request: it resumes
  out = wrap->GetOutput();
  double largest = out->GetNumberOfPoints() == whole->GetNumberOfPoints() ? 0 : 1e300;
  for (vtkIdType i = 0; largest < 1e300 && i < whole->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    whole->GetPoint(i, a);
    out->GetPoint(i, b);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  SW_CHECK(largest < 1e-6 * kRadius, // restarted from step 1 cached: not bit for bit
    "then resumed: the wrap of a run never stopped, to 1e-6 of its size ("
      << out->GetNumberOfPoints() << " and " << whole->GetNumberOfPoints()
      << " vertices, largest difference " << largest << ")");
}
} // namespace

int TestHonestResults(int, char*[])
{
  inwardFacingTarget();
  doubleSidedTarget();
  notLanded();
  farFromOrigin();
  sand();
  abortInSetup();
  return testing::finish("TestHonestResults");
}
