// vtkMeshSignedDistance as a user drives it through a VTK pipeline: the grid it places, explicit
// grids, field data, progress, abort, and an open mesh.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"

#include <vtkCallbackCommand.h>

#include <algorithm>
#include <vtkClipPolyData.h>
#include <vtkCommand.h>
#include <vtkContourFilter.h>
#include <vtkDiskSource.h>
#include <vtkPlane.h>
#include <vtkReverseSense.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>

namespace
{
struct Events
{
  std::vector<double> progress;
  int warnings = 0;
  bool abortAt = false;
  double abortFraction = 2;
};

void onEvent(vtkObject* caller, unsigned long id, void* clientData, void* callData)
{
  auto* events = static_cast<Events*>(clientData);
  if (id == vtkCommand::ProgressEvent)
  {
    const double fraction = *static_cast<double*>(callData);
    events->progress.push_back(fraction);
    if (fraction >= events->abortFraction)
    {
      vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
    }
  }
  else if (id == vtkCommand::WarningEvent)
  {
    ++events->warnings;
  }
}

vtkSmartPointer<vtkPolyData> sphere(int resolution)
{
  vtkNew<vtkSphereSource> s;
  s->SetRadius(1.0);
  s->SetThetaResolution(resolution);
  s->SetPhiResolution(resolution);
  s->Update();
  return s->GetOutput();
}

double fieldValue(vtkImageData* image, const char* name)
{
  vtkDataArray* a = image->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : -1;
}
} // namespace

int TestMeshSignedDistanceFilter(int, char*[])
{
  Events events;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(onEvent);
  observer->SetClientData(&events);

  vtkNew<vtkMeshSignedDistance> filter;
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->AddObserver(vtkCommand::WarningEvent, observer);
  filter->SetInputData(sphere(32));
  filter->SetResolution(60);
  filter->SetOffsetFactor(1.0); // the paper's box
  filter->Update();
  vtkImageData* image = filter->GetOutput();

  // The grid: 60 cells along the longest axis, equal spacing, bounds 1.1 x 3 = 3.3 times the
  // sphere's.
  int dims[3];
  double spacing[3], bounds[6];
  image->GetDimensions(dims);
  image->GetSpacing(spacing);
  image->GetBounds(bounds);
  SW_CHECK(std::max({ dims[0], dims[1], dims[2] }) == 61,
    "Resolution counts cells along the longest axis");
  SW_CHECK(spacing[0] == spacing[1] && spacing[1] == spacing[2], "equal spacing on all axes");
  SW_CHECK(std::abs((bounds[1] - bounds[0]) - 3.3 * 2.0) < 1e-9 * 2.0 + spacing[0],
    "BoxScale 1.1 and OffsetFactor 1 give 3.3 times the mesh extent");
  {
    vtkNew<vtkMeshSignedDistance> placed; // the default box: 1.1 x 1.3 = 1.43 times the sphere's
    placed->SetInputData(sphere(32));
    placed->SetResolution(60);
    placed->Update();
    double b[6];
    placed->GetOutput()->GetBounds(b);
    SW_CHECK(
      std::abs((b[1] - b[0]) - 1.43 * 2.0) < 1e-9 * 2.0 + placed->GetOutput()->GetSpacing()[0],
      "by default BoxScale 1.1 and OffsetFactor 0.15 give 1.43 times the mesh extent");
  }
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  SW_CHECK(values != nullptr, "a float point array named SignedDistance");
  SW_CHECK(image->GetPointData()->GetScalars() == values, "SignedDistance is the active scalars");
  SW_CHECK(fieldValue(image, "Signed") == 1, "field data Signed = 1 for a closed mesh");
  // The ranges come with the field (found on every core), so ParaView does not scan the grid for
  // them again; they are the values' own.
  SW_CHECK(values && values->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()) &&
      values->GetInformation()->Has(vtkAbstractArray::PER_FINITE_COMPONENT()),
    "the field's ranges are kept with it");
  if (values)
  {
    const auto extremes = std::minmax_element(
      values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
    double range[2], finite[2];
    values->GetRange(range);
    values->GetFiniteRange(finite);
    SW_CHECK(range[0] == *extremes.first && range[1] == *extremes.second && finite[0] == range[0] &&
        finite[1] == range[1],
      "the kept ranges are the least and greatest values: ["
        << range[0] << ", " << range[1] << "], finite [" << finite[0] << ", " << finite[1] << "]");
  }
  SW_CHECK(values && values->GetRange()[0] < -0.95 && values->GetRange()[0] > -1.0,
    "the centre is about one radius inside");

  // Progress: increasing, reaching 1.
  SW_CHECK(!events.progress.empty() && events.progress.back() == 1.0, "progress ends at 1");
  SW_CHECK(
    std::is_sorted(events.progress.begin(), events.progress.end()), "progress never goes back");
  SW_CHECK(events.progress.size() >= 8,
    "progress reported through the stages (" << events.progress.size() << ")");

  // The zero contour lies on the sphere.
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(filter->GetOutputPort());
  contour->SetValue(0, 0.0);
  contour->Update();
  double worst = 0;
  vtkPoints* points = contour->GetOutput()->GetPoints();
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    worst = std::max(worst, std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1.0));
  }
  SW_CHECK(points && points->GetNumberOfPoints() > 100 && worst < 0.5 * spacing[0],
    "the zero contour lies on the sphere (worst " << worst << ")");

  // CellSize overrides Resolution.
  filter->SetCellSize(0.1);
  filter->Update();
  filter->GetOutput()->GetSpacing(spacing);
  SW_CHECK(spacing[0] == 0.1, "CellSize sets the spacing");
  filter->SetCellSize(0);

  // An explicit grid, as Resample To Image would give.
  filter->UseExplicitGridOn();
  filter->SetOutputBounds(-2, 2, -1, 1, 0, 1.5);
  filter->SetOutputDimensions(41, 21, 16);
  filter->Update();
  filter->GetOutput()->GetDimensions(dims);
  filter->GetOutput()->GetBounds(bounds);
  SW_CHECK(dims[0] == 41 && dims[1] == 21 && dims[2] == 16, "explicit dimensions");
  SW_CHECK(std::abs(bounds[0] + 2) < 1e-12 && std::abs(bounds[1] - 2) < 1e-12 &&
      std::abs(bounds[5] - 1.5) < 1e-12,
    "explicit bounds");
  const testing::FieldErrors explicitErrors = testing::compareWithReference(
    filter->GetOutput(), testing::triangulated(sphere(32)), true, true);
  testing::checkAccuracy("explicit grid", explicitErrors, true);
  filter->UseExplicitGridOff();

  // Eikonal sweep and unsigned output are options.
  filter->SetSweepMethod(vtkMeshSignedDistance::EIKONAL);
  filter->ComputeSignOff();
  filter->Update();
  values =
    vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetArray("SignedDistance"));
  SW_CHECK(values && values->GetRange()[0] >= 0, "ComputeSign off gives an unsigned field");
  SW_CHECK(fieldValue(filter->GetOutput(), "Signed") == 0, "field data Signed = 0 when unsigned");
  filter->SetSweepMethod(vtkMeshSignedDistance::CLOSEST_POINT);
  filter->ComputeSignOn();

  // Abort: an observer sets AbortExecute halfway; the output is empty and the next run works.
  events.progress.clear();
  events.abortFraction = 0.5;
  filter->SetResolution(80);
  filter->Update();
  SW_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0, "an aborted run leaves an empty output");
  // The executive reports 1.0 when RequestData returns; before it, the filter stopped at the next
  // check.
  const auto late = std::count_if(
    events.progress.begin(), events.progress.end(), [](double p) { return p >= 0.5 && p < 1.0; });
  SW_CHECK(late == 1,
    "the run stopped at the first check after the abort (" << late << " reports after it)");
  events.abortFraction = 2;
  filter->SetAbortExecute(0);
  filter->Modified();
  filter->Update();
  SW_CHECK(filter->GetOutput()->GetNumberOfPoints() == 81LL * 81 * 81,
    "the pipeline runs again after an abort");

  // A mesh whose triangles face inwards: still negative inside, said in DistanceStatus; no warning
  // (the field is right).
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(sphere(32));
  reverse->ReverseCellsOn();
  reverse->Update();
  events.warnings = 0;
  filter->SetInputData(reverse->GetOutput());
  filter->SetResolution(40);
  filter->Update();
  values =
    vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetArray("SignedDistance"));
  SW_CHECK(fieldValue(filter->GetOutput(), "Signed") == 1 && values && values->GetRange()[0] < -0.9,
    "an inside-out mesh still gives negative distances inside");
  SW_CHECK(events.warnings == 0, "and no warning");
  auto* inverted = vtkStringArray::SafeDownCast(
    filter->GetOutput()->GetFieldData()->GetAbstractArray("DistanceStatus"));
  SW_CHECK(inverted && inverted->GetValue(0).find("face inwards") != std::string::npos,
    "DistanceStatus says its triangles face inwards: " << (inverted ? inverted->GetValue(0)
                                                                    : std::string("none")));
  testing::checkAccuracy("inside-out sphere",
    testing::compareWithReference(
      filter->GetOutput(), testing::triangulated(sphere(32)), true, true),
    true);

  // An open mesh (a sphere with its top cut off): signed by the generalized winding number, said
  // so in DistanceStatus without a warning (the field is right), every sampled node farther than a
  // cell on the winding number's side.
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0, 0, 0.5);
  plane->SetNormal(0, 0, -1);
  vtkNew<vtkClipPolyData> clip;
  clip->SetInputData(sphere(32));
  clip->SetClipFunction(plane);
  clip->Update();
  events.warnings = 0;
  filter->SetInputData(clip->GetOutput());
  filter->SetResolution(40);
  filter->Update();
  image = filter->GetOutput();
  SW_CHECK(fieldValue(image, "Signed") == 1, "an open mesh gives a signed field");
  SW_CHECK(events.warnings == 0, "and no warning");
  auto* status =
    vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("DistanceStatus"));
  SW_CHECK(status && status->GetValue(0).find("signed by the generalized winding number") == 0,
    "DistanceStatus says how: " << (status ? status->GetValue(0) : std::string("none")));
  const testing::FieldErrors openErrors =
    testing::compareWithReference(image, testing::triangulated(clip->GetOutput()), true, false);
  testing::checkAccuracy("open sphere", openErrors, false);
  const testing::SignSample openSigns =
    testing::sampleSigns(image, testing::triangulated(clip->GetOutput()), 4000);
  SW_CHECK(openSigns.disagreeing == 0 && openSigns.far > 1000,
    "the open sphere's signs agree with its winding number (" << openSigns.disagreeing << " of "
                                                              << openSigns.far << ")");

  // A disc encloses nothing: unsigned, flagged, and a warning.
  vtkNew<vtkDiskSource> disc;
  disc->SetInnerRadius(0);
  disc->SetCircumferentialResolution(32);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(disc->GetOutputPort());
  triangles->Update();
  events.warnings = 0;
  filter->SetInputData(triangles->GetOutput());
  filter->Update();
  image = filter->GetOutput();
  SW_CHECK(fieldValue(image, "Signed") == 0, "a disc gives an unsigned field");
  SW_CHECK(events.warnings > 0, "and a warning");
  status = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("DistanceStatus"));
  SW_CHECK(status && status->GetValue(0).find("unsigned: the surface encloses nothing") == 0,
    "DistanceStatus says why: " << (status ? status->GetValue(0) : std::string("none")));
  values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  SW_CHECK(values && values->GetRange()[0] >= 0, "the unsigned field has no negative values");

  return testing::finish("TestMeshSignedDistanceFilter");
}
