// Bad input never crashes and never corrupts: each case gets a clear error or warning and an empty
// (or valid) output, and the same filter then computes a good input. Run under AddressSanitizer in
// CI.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkSphereSource.h>

#include <functional>
#include <limits>

namespace
{
struct Messages
{
  std::vector<std::string> errors, warnings;
};

void capture(vtkObject*, unsigned long id, void* clientData, void* callData)
{
  auto* m = static_cast<Messages*>(clientData);
  (id == vtkCommand::ErrorEvent ? m->errors : m->warnings)
    .push_back(static_cast<const char*>(callData));
}

vtkSmartPointer<vtkPolyData> mesh(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::vector<vtkIdType>>& polys,
  const std::vector<std::vector<vtkIdType>>& lines = {})
{
  vtkNew<vtkPoints> p;
  for (const auto& x : points)
  {
    p->InsertNextPoint(x.data());
  }
  vtkNew<vtkCellArray> cells, lineCells;
  for (const auto& c : polys)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  for (const auto& c : lines)
  {
    lineCells->InsertNextCell(static_cast<vtkIdType>(c.size()), c.data());
  }
  auto m = vtkSmartPointer<vtkPolyData>::New();
  m->SetPoints(p);
  m->SetPolys(cells);
  m->SetLines(lineCells);
  return m;
}

const std::vector<std::array<double, 3>> kTetPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
  { 0, 0, 1 } };
const std::vector<std::vector<vtkIdType>> kTet = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 },
  { 1, 2, 3 } };

enum class Expect
{
  ErrorAndEmpty,
  ValidOutput
};

void run(const std::string& name, vtkMeshSignedDistance* filter, vtkPolyData* input, Expect expect,
  const std::string& mustSay, const std::function<void(vtkMeshSignedDistance*)>& configure = {})
{
  Messages messages;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(capture);
  observer->SetClientData(&messages);
  const unsigned long e = filter->AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long w = filter->AddObserver(vtkCommand::WarningEvent, observer);
  filter->SetInputData(input);
  filter->SetResolution(24);
  if (configure)
  {
    configure(filter);
  }
  filter->Update();
  filter->RemoveObserver(e);
  filter->RemoveObserver(w);

  std::string said;
  for (const auto& m : messages.errors)
    said += "[error] " + m;
  for (const auto& m : messages.warnings)
    said += "[warning] " + m;
  std::cout << name << ": " << (said.empty() ? "(nothing said)" : said.substr(said.find("): ") + 3))
            << std::endl;

  vtkImageData* out = filter->GetOutput();
  if (expect == Expect::ErrorAndEmpty)
  {
    SW_CHECK(!messages.errors.empty(), name << ": an error is reported");
    SW_CHECK(out->GetNumberOfPoints() == 0, name << ": the output is empty");
  }
  else
  {
    SW_CHECK(out->GetNumberOfPoints() > 0, name << ": a valid output");
    auto* values = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("SignedDistance"));
    bool finite = values != nullptr;
    for (vtkIdType i = 0; values && i < values->GetNumberOfValues(); ++i)
    {
      finite = finite && std::isfinite(values->GetValue(i));
    }
    SW_CHECK(finite, name << ": every value finite");
  }
  SW_CHECK(mustSay.empty() || said.find(mustSay) != std::string::npos,
    name << ": the message says '" << mustSay << "'");

  // Whatever happened, the same filter computes a good mesh next, with default settings.
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  filter->SetInputData(sphere->GetOutput());
  filter->SetResolution(24);
  filter->SetCellSize(0);
  filter->SetBoxScale(1.1);
  filter->SetOffsetFactor(1.0);
  filter->UseExplicitGridOff();
  filter->Update();
  SW_CHECK(
    filter->GetOutput()->GetNumberOfPoints() == 25 * 25 * 25, name << ": the pipeline lives on");
}
} // namespace

int TestMeshSignedDistanceBadInput(int, char*[])
{
  vtkNew<vtkMeshSignedDistance> filter;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  run("empty polydata", filter, vtkNew<vtkPolyData>(), Expect::ErrorAndEmpty, "no polygons");
  // Without polygons the points are measured (issue #13): a cloud, or the points of lines.
  run("points without cells", filter, mesh(kTetPoints, {}), Expect::ValidOutput, "");
  run(
    "lines only", filter, mesh(kTetPoints, {}, { { 0, 1 }, { 1, 2, 3 } }), Expect::ValidOutput, "");
  run("collinear points", filter, mesh({ { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } }, {}),
    Expect::ValidOutput, "");
  run("coplanar points", filter, mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }, {}),
    Expect::ValidOutput, "");
  run("one point", filter, mesh({ { 1, 2, 3 } }, {}), Expect::ErrorAndEmpty, "no extent");
  run("all points equal", filter, mesh({ { 1, 2, 3 }, { 1, 2, 3 }, { 1, 2, 3 } }, {}),
    Expect::ErrorAndEmpty, "no extent");
  run("a NaN point", filter, mesh({ { 0, 0, 0 }, { 1, nan, 0 }, { 0, 1, 0 } }, {}),
    Expect::ErrorAndEmpty, "NaN");
  run("lines beside a closed mesh", filter, mesh(kTetPoints, kTet, { { 0, 1 } }),
    Expect::ValidOutput, "Ignoring 1 lines");
  run("NaN coordinate", filter,
    mesh({ { 0, 0, 0 }, { 1, nan, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, kTet), Expect::ErrorAndEmpty,
    "NaN");
  run("infinite coordinate", filter,
    mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, inf, 0 }, { 0, 0, 1 } }, kTet), Expect::ErrorAndEmpty,
    "infinite");
  run("all triangles degenerate", filter,
    mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, { { 0, 1, 2 }, { 0, 0, 1 } }),
    Expect::ErrorAndEmpty, "degenerate");
  run("point id out of range", filter, mesh(kTetPoints, { { 0, 1, 7 } }), Expect::ErrorAndEmpty,
    "out of range");
  run("single triangle (flat box)", filter, mesh(kTetPoints, { { 0, 1, 2 } }), Expect::ValidOutput,
    "unsigned");
  run("some degenerate and non-manifold triangles", filter,
    mesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 2, 0, 0 }, { 1, 1, 1 } },
      { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 }, { 0, 1, 4 }, { 1, 2, 5 },
        { 0, 1, 5 } }),
    Expect::ValidOutput, "");
  run("Resolution 0", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty, "Resolution",
    [](vtkMeshSignedDistance* f) { f->SetResolution(0); });
  run("Resolution negative", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty, "Resolution",
    [](vtkMeshSignedDistance* f) { f->SetResolution(-10); });
  run("CellSize negative", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty, "Cell Size is -0.1: it must be at least 0",
    [](vtkMeshSignedDistance* f) { f->SetCellSize(-0.1); });
  run("BoxScale zero", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty, "Box Scale is 0: it must be from 1 to 10",
    [](vtkMeshSignedDistance* f) { f->SetBoxScale(0); });
  run("OffsetFactor negative", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "Offset Factor is -1: it must be from 0 to 10", [](vtkMeshSignedDistance* f) { f->SetOffsetFactor(-1); });
  run("Resolution beyond the panel's range", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "Resolution is 200000: it must be from 1 to 1024",
    [](vtkMeshSignedDistance* f) { f->SetResolution(200000); });
  run("cell size too small for memory", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "would need", [](vtkMeshSignedDistance* f) { f->SetCellSize(1e-6); });
  run("explicit grid, inverted bounds", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "bounds", [](vtkMeshSignedDistance* f) {
      f->UseExplicitGridOn();
      f->SetOutputBounds(1, -1, 0, 1, 0, 1);
    });
  run("explicit grid, one node", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "Output Dimensions is 1: it must be at least 2", [](vtkMeshSignedDistance* f) {
      f->UseExplicitGridOn();
      f->SetOutputBounds(-1, 1, -1, 1, -1, 1);
      f->SetOutputDimensions(1, 10, 10);
    });
  run("explicit grid too large for memory", filter, mesh(kTetPoints, kTet), Expect::ErrorAndEmpty,
    "would need", [](vtkMeshSignedDistance* f) {
      f->UseExplicitGridOn();
      f->SetOutputBounds(-1, 1, -1, 1, -1, 1);
      f->SetOutputDimensions(100000, 100000, 100000);
    });
  return testing::finish("TestMeshSignedDistanceBadInput");
}
