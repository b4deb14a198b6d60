// Shrink Wrap and Mesh Signed Distance fed what crashed them (issue #8): composite inputs on every
// port, a starved step cache, corrupt starting surfaces, absurd step counts and request times,
// short or non-finite distance fields, coordinates too large for the field, aborts, cells naming
// points that do not exist. Each gets a correct result or a clear error and an empty output, and
// the filter computes a good input afterwards. Run under AddressSanitizer and UBSan in CI.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataObjectTypes.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPartitionedDataSet.h>
#include <vtkPartitionedDataSetCollection.h>
#include <vtkSphereSource.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <functional>
#include <limits>

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

vtkSmartPointer<vtkPolyData> sphere(double x = 0, double radius = 1)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(x, 0, 0);
  source->SetRadius(radius);
  source->SetThetaResolution(16);
  source->SetPhiResolution(16);
  source->Update();
  return source->GetOutput();
}

struct Said
{
  int errors = 0;
  std::string text;
};

// Runs `run` and returns what the algorithm said through error and warning events.
Said whileSaying(vtkAlgorithm* algorithm, const std::function<void()>& run)
{
  Said said;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&said);
  observer->SetCallback([](vtkObject*, unsigned long id, void* data, void* message) {
    auto* s = static_cast<Said*>(data);
    s->errors += id == vtkCommand::ErrorEvent;
    s->text += static_cast<const char*>(message);
  });
  const unsigned long e = algorithm->AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long w = algorithm->AddObserver(vtkCommand::WarningEvent, observer);
  run();
  algorithm->RemoveObserver(e);
  algorithm->RemoveObserver(w);
  return said;
}

int stepOf(vtkDataObject* data)
{
  vtkDataArray* a = data->GetFieldData()->GetArray("StepIndex");
  return a ? static_cast<int>(a->GetTuple1(0)) : -1;
}

std::vector<double> pointsOf(vtkDataObject* data)
{
  std::vector<double> p;
  auto* mesh = vtkPolyData::SafeDownCast(data);
  for (vtkIdType i = 0; mesh && i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    p.insert(p.end(), x, x + 3);
  }
  return p;
}

vtkSmartPointer<vtkShrinkWrapFilter> wrapOf(vtkDataObject* target, int steps = 5)
{
  auto wrap = vtkSmartPointer<vtkShrinkWrapFilter>::New();
  wrap->SetInputData(target);
  wrap->SetResolution(24);
  wrap->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE); // a known vertex count (162) to check
  wrap->SetRemeshing(false);
  wrap->SetSubdivisionLevel(2);
  wrap->SetNumberOfSteps(steps);
  return wrap;
}

// The filter still wraps a good target after whatever came before.
void livesOn(vtkShrinkWrapFilter* wrap, const std::string& name)
{
  wrap->SetInputData(0, sphere());
  wrap->SetInputConnection(1, nullptr);
  wrap->SetInputConnection(2, nullptr);
  wrap->Update();
  SW_CHECK(
    pointsOf(wrap->GetOutputDataObject(0)).size() == 3 * 162, name << ": the pipeline lives on");
}

// Composite targets: Shrink Wrap wraps them block by block; each block's wrap equals
// the wrap of that mesh alone. Mesh Signed Distance takes the composite whole: one field of all
// meshes.
void compositeInputs()
{
  vtkSmartPointer<vtkPolyData> a = sphere(0), b = sphere(3, 0.5);
  auto lone = wrapOf(a);
  lone->Update();
  const std::vector<double> wrapA = pointsOf(lone->GetOutput());

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, a);
  blocks->SetBlock(1, b);
  vtkNew<vtkPartitionedDataSet> parts;
  parts->SetPartition(0, a);
  parts->SetPartition(1, b);
  vtkNew<vtkPartitionedDataSetCollection> collection;
  collection->SetPartitionedDataSet(0, parts);
  for (vtkDataObject* input : std::initializer_list<vtkDataObject*>{ blocks, parts, collection })
  {
    const std::string name = input->GetClassName();
    auto wrap = wrapOf(input);
    const Said said = whileSaying(wrap, [&] { wrap->Update(); });
    auto* out = vtkCompositeDataSet::SafeDownCast(wrap->GetOutputDataObject(0));
    const auto leaves = vtkCompositeDataSet::GetDataSets<vtkPolyData>(out);
    SW_CHECK(said.errors == 0 && leaves.size() == 2,
      name << " target: a wrap per mesh (" << leaves.size() << ")");
    SW_CHECK(!leaves.empty() && pointsOf(leaves[0]) == wrapA,
      name << " target: the first wrap is that of its mesh alone");

    vtkNew<vtkMeshSignedDistance> sdf;
    sdf->SetInputData(input);
    sdf->SetResolution(24);
    sdf->Update();
    vtkImageData* field = sdf->GetOutput();
    double origin[3];
    field->GetOrigin(origin);
    // The field of both meshes: negative at both centres.
    auto valueAt = [&](double x) {
      const int i = static_cast<int>(std::lround((x - origin[0]) / field->GetSpacing()[0]));
      const int j = static_cast<int>(std::lround(-origin[1] / field->GetSpacing()[1]));
      const int k = static_cast<int>(std::lround(-origin[2] / field->GetSpacing()[2]));
      return field->GetScalarComponentAsDouble(i, j, k, 0);
    };
    SW_CHECK(field->GetNumberOfPoints() > 0 && valueAt(0) < 0 && valueAt(3) < 0,
      name << " into Mesh Signed Distance: one field, inside both meshes (" << valueAt(0) << ", "
           << valueAt(3) << ")");

    // The other choices (issue #14): all blocks wrapped together, one surface, equal to the wrap of
    // the meshes appended into one; a field per block, each equal to its mesh's field alone.
    vtkNew<vtkAppendPolyData> append;
    append->AddInputData(a);
    append->AddInputData(b);
    append->Update();
    auto both = wrapOf(append->GetOutput());
    both->Update();
    auto together = wrapOf(input);
    together->SetWrapPerBlock(false);
    const Said saidTogether = whileSaying(together, [&] { together->Update(); });
    const std::vector<double> wrapBoth = pointsOf(both->GetOutputDataObject(0));
    SW_CHECK(saidTogether.errors == 0 && !wrapBoth.empty() &&
        pointsOf(together->GetOutputDataObject(0)) == wrapBoth,
      name << " target, blocks wrapped together: one surface, that of both meshes as one ("
           << together->GetOutputDataObject(0)->GetClassName() << ")");
    // Back in time: the session's cached step, not a new session (the blocks are appended only to
    // start one).
    const int computed = together->GetNumberOfComputedSteps();
    together->UpdateTimeStep(2 * together->GetTimePerStep());
    both->UpdateTimeStep(2 * both->GetTimePerStep());
    SW_CHECK(together->GetNumberOfComputedSteps() == computed &&
        stepOf(together->GetOutputDataObject(0)) == 2 &&
        pointsOf(together->GetOutputDataObject(0)) == pointsOf(both->GetOutputDataObject(0)),
      name << " target, blocks wrapped together: step 2 from the cache equals the appended meshes' "
              "step 2");
    vtkNew<vtkMeshSignedDistance> alone;
    alone->SetInputData(b);
    alone->SetResolution(24);
    alone->Update();
    vtkNew<vtkMeshSignedDistance> perBlock;
    perBlock->SetInputData(input);
    perBlock->SetResolution(24);
    perBlock->FieldPerBlockOn();
    std::vector<double> progress;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetClientData(&progress);
    onProgress->SetCallback([](vtkObject*, unsigned long, void* seen, void* amount) {
      static_cast<std::vector<double>*>(seen)->push_back(*static_cast<double*>(amount));
    });
    perBlock->AddObserver(vtkCommand::ProgressEvent, onProgress);
    perBlock->Update();
    SW_CHECK(!progress.empty() && std::is_sorted(progress.begin(), progress.end()) &&
        progress.back() <= 1.0 &&
        std::count_if(progress.begin(), progress.end(), [](double p) { return p > 0.5; }) > 0,
      name << " into Mesh Signed Distance, a field per block: one progress bar over both blocks ("
           << progress.size() << " reports)");
    vtkDataObject* fields = perBlock->GetOutputDataObject(0);
    const auto images = vtkCompositeDataSet::GetDataSets<vtkImageData>(fields);
    auto valuesOf = [](vtkImageData* image) {
      vtkDataArray* v = image ? image->GetPointData()->GetArray("SignedDistance") : nullptr;
      std::vector<double> out;
      for (vtkIdType i = 0; v && i < v->GetNumberOfTuples(); ++i)
      {
        out.push_back(v->GetTuple1(i));
      }
      return out;
    };
    SW_CHECK(std::string(fields->GetClassName()) == name && images.size() == 2 &&
        !valuesOf(alone->GetOutput()).empty() &&
        valuesOf(images[1]) == valuesOf(alone->GetOutput()) &&
        images[1]->GetBounds()[0] == alone->GetOutput()->GetBounds()[0],
      name << " into Mesh Signed Distance, a field per block: " << fields->GetClassName() << " of "
           << images.size() << " images, the second equal to its mesh's field alone");

    // A composite where an image or a starting surface belongs: the executive refuses the type (its
    // own error names it), never a crash.
    for (int port : { 1, 2 })
    {
      auto withPort = wrapOf(a);
      withPort->SetInputData(port, input);
      withPort->Update();
      SW_CHECK(pointsOf(withPort->GetOutputDataObject(0)).empty(),
        name << " on port " << port << ": no output");
      livesOn(withPort, name + " on port " + std::to_string(port));
    }
  }

  // A block that is not a polygon mesh (tetrahedra) counts by its outer surface, as Extract Surface
  // gives it: the field is one of both blocks, negative inside the tetrahedron.
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(i == 1, i == 2, i == 3);
  }
  grid->SetPoints(points);
  const vtkIdType tet[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  vtkNew<vtkMultiBlockDataSet> mixed;
  mixed->SetBlock(0, a);
  mixed->SetBlock(1, grid);
  vtkNew<vtkMeshSignedDistance> sdf;
  sdf->SetInputData(mixed);
  sdf->SetResolution(24);
  const Said said = whileSaying(sdf, [&] { sdf->Update(); });
  double inside[3] = { 0.2, 0.2, 0.2 };
  const vtkIdType node = sdf->GetOutput()->FindPoint(inside);
  vtkDataArray* field = sdf->GetOutput()->GetPointData()->GetArray("SignedDistance");
  SW_CHECK(said.errors == 0 && node >= 0 && field && field->GetTuple1(node) < 0,
    "a block of tetrahedra into Mesh Signed Distance: measured by its outer surface (negative "
    "inside)");
  auto wrap = wrapOf(mixed);
  whileSaying(wrap, [&] { wrap->Update(); });
  const auto leaves = vtkCompositeDataSet::GetDataSets<vtkPolyData>(wrap->GetOutputDataObject(0));
  SW_CHECK(!leaves.empty() && pointsOf(leaves[0]) == wrapA,
    "a block of tetrahedra beside a mesh: the mesh is wrapped");
}

// A composite target over time (issue #14): every block moves through the steps as its mesh alone
// does, each from a session of its own (before, time did not move at all for a composite); pieces
// share the blocks out; a distance field beside a composite target is refused with a message.
void compositeTimeSteps()
{
  vtkSmartPointer<vtkPolyData> a = sphere(0), b = sphere(3, 0.5);
  const double tau = wrapOf(a)->GetTimePerStep();
  auto alone = [&](vtkPolyData* mesh, int step) {
    auto w = wrapOf(mesh, 10);
    w->UpdateTimeStep(step * tau);
    return pointsOf(w->GetOutput());
  };
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, a);
  blocks->SetBlock(1, b);
  auto wrap = wrapOf(blocks, 10);
  for (int step : { 10, 4, 10, 7 })
  {
    wrap->UpdateTimeStep(step * tau);
    const auto leaves = vtkCompositeDataSet::GetDataSets<vtkPolyData>(wrap->GetOutputDataObject(0));
    SW_CHECK(leaves.size() == 2 && stepOf(leaves[0]) == step && stepOf(leaves[1]) == step &&
        pointsOf(leaves[0]) == alone(a, step) && pointsOf(leaves[1]) == alone(b, step),
      "composite target at step " << step << ": each block is its mesh's wrap at that step");
  }
  wrap->UpdatePiece(1, 2, 0);
  const auto piece = vtkCompositeDataSet::GetDataSets<vtkPolyData>(wrap->GetOutputDataObject(0));
  SW_CHECK(
    piece.size() == 2 && piece[0]->GetNumberOfPoints() == 0 && pointsOf(piece[1]) == alone(b, 7),
    "piece 1 of 2 wraps the smaller block only (the larger goes to piece 0; " << piece.size()
                                                                              << " blocks)");

  vtkNew<vtkImageData> field;
  field->SetDimensions(4, 4, 4);
  auto withField = wrapOf(blocks);
  withField->SetInputData(1, field);
  const Said said = whileSaying(withField, [&] { withField->Update(); });
  const auto none =
    vtkCompositeDataSet::GetDataSets<vtkPolyData>(withField->GetOutputDataObject(0));
  SW_CHECK(said.errors == 1 && said.text.find("block by block") != std::string::npos &&
      std::all_of(
        none.begin(), none.end(), [](vtkPolyData* m) { return m->GetNumberOfPoints() == 0; }),
    "a distance field beside a composite target: refused, said why (" << said.text << ")");
  livesOn(withField, "composite target with a field");
}

// Cache Memory Limit below three steps (0, or 1 MiB with a large surface): the thinning stops at
// step 0, the newest and the one shown. Asked for step 7 after the end, it recomputes step 7
// exactly.
void starvedCache()
{
  for (double limit : { 0.0, 1e-9, 1.0 })
  {
    auto wrap = wrapOf(sphere(), 40);
    wrap->SetSubdivisionLevel(5);
    wrap->SetCacheMemoryMiB(limit);
    wrap->Update();
    wrap->UpdateTimeStep(7 * 0.015);
    auto fresh = wrapOf(sphere(), 7);
    fresh->SetSubdivisionLevel(5);
    fresh->Update();
    SW_CHECK(
      stepOf(wrap->GetOutput()) == 7 && pointsOf(wrap->GetOutput()) == pointsOf(fresh->GetOutput()),
      "Cache Memory Limit " << limit << " MiB: back to step 7, the same surface as a fresh run");
  }
}

// A closed sphere around the target, spoiled: an id out of range or negative, a point not finite.
void corruptStartingSurfaces()
{
  struct Case
  {
    const char* name;
    std::function<void(std::vector<vtkIdType>&, vtkPoints*)> spoil;
  };
  const std::vector<Case> cases = {
    { "a triangle naming point 100000",
      [](std::vector<vtkIdType>& ids, vtkPoints*) { ids[4] = 100000; } },
    { "a negative point id", [](std::vector<vtkIdType>& ids, vtkPoints*) { ids[5] = -5; } },
    { "a NaN point", [](std::vector<vtkIdType>&, vtkPoints* p) { p->SetPoint(3, kNaN, 0, 0); } },
    { "an infinite point",
      [](std::vector<vtkIdType>&, vtkPoints* p) { p->SetPoint(3, 0, kInf, 0); } },
  };
  for (const Case& c : cases)
  {
    vtkSmartPointer<vtkPolyData> good = sphere(0, 1.5);
    std::vector<vtkIdType> ids;
    for (const auto& t : testing::triangulated(good).triangles)
    {
      ids.insert(ids.end(), t.begin(), t.end());
    }
    vtkNew<vtkPoints> points;
    points->DeepCopy(good->GetPoints());
    c.spoil(ids, points);
    vtkNew<vtkCellArray> triangles;
    for (size_t k = 0; k < ids.size(); k += 3)
    {
      triangles->InsertNextCell(3, &ids[k]);
    }
    vtkNew<vtkPolyData> start;
    start->SetPoints(points);
    start->SetPolys(triangles);
    auto wrap = wrapOf(sphere(0, 0.5));
    wrap->SetInputData(2, start);
    const Said said = whileSaying(wrap, [&] { wrap->Update(); });
    SW_CHECK(said.errors > 0 && wrap->GetOutput()->GetNumberOfPoints() == 0,
      "InitialSurface with " << c.name << ": an error and an empty output");
    livesOn(wrap, c.name);
  }
}

void absurdStepsAndTimes()
{
  auto wrap = wrapOf(sphere());
  for (int steps : { std::numeric_limits<int>::max(), 1000000000, -7 })
  {
    wrap->SetNumberOfSteps(steps);
    wrap->UpdateInformation();
    const int n =
      wrap->GetOutputInformation(0)->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const Said said = whileSaying(wrap, [&] { wrap->Update(); });
    SW_CHECK(n == 0 && said.errors == 1 &&
        said.text.find("Number Of Steps is " + std::to_string(steps) + ": it must be from 0 to " +
          std::to_string(vtkShrinkWrapFilter::kMaxSteps)) != std::string::npos &&
        wrap->GetOutput()->GetNumberOfPoints() == 0,
      "Number Of Steps " << steps << ": refused with the label and the range, no time steps (" << n
                         << "), an empty output (" << said.text << ")");
  }
  wrap->SetNumberOfSteps(5);
  for (double t : { 5e7, 1e9, kInf, 1e300, kNaN })
  {
    wrap->UpdateTimeStep(t);
    SW_CHECK(stepOf(wrap->GetOutput()) == 5,
      "time " << t << ": the last step (" << stepOf(wrap->GetOutput()) << ")");
  }
  for (double t : { -1.0, -kInf, -1e300 })
  {
    wrap->UpdateTimeStep(t);
    SW_CHECK(stepOf(wrap->GetOutput()) == 0,
      "time " << t << ": step 0 (" << stepOf(wrap->GetOutput()) << ")");
  }
}

// Sizes that would make no wrap: a clear error naming the panel's label, an empty output, and the
// pipeline lives on. Sizes that make a useless wrap: the wrap, and a warning saying why.
void absurdSizes()
{
  auto wrap = wrapOf(sphere());
  wrap->SetRemeshing(true);
  wrap->SetStartingShape(vtkShrinkWrapFilter::OFFSET_SURFACE);
  wrap->SetResolution(48); // cells of 0.09: the automatic L, 0.069, is 0.76 cells
  struct Case
  {
    std::string name;
    std::function<void()> set;
    std::string said; // expected in the message
    bool wraps;       // a warning and a wrap, else an error and no wrap
  };
  const Case cases[] = {
    { "Target Edge Length 1e-9", [&] { wrap->SetTargetEdgeLength(1e-9); },
      "Target Edge Length 1e-09 would make about", false },
    { "Target Edge Length -1", [&] { wrap->SetTargetEdgeLength(-1); },
      "Target Edge Length is -1: it must be at least 0", false },
    { "Target Edge Length 1e9", [&] { wrap->SetTargetEdgeLength(1e9); },
      "Target Edge Length 1e+09 leaves the wrap at most about 4 vertices", true },
    // Edges the field cannot carry (its steps fail under about 0.4 cells), a field too coarse
    // for the start and the gap closing: refused before the run, naming the Resolution that can.
    { "Target Edge Length 0.005 at Resolution 80",
      [&] {
        wrap->SetResolution(80);
        wrap->SetTargetEdgeLength(0.005);
      },
      "under the 0.45 its steps can carry: raise Resolution to at least", false },
    { "Resolution 12",
      [&] {
        wrap->SetResolution(12);
        wrap->SetTargetEdgeLength(0);
      },
      "Resolution 12 is too coarse for the start", false },
    { "Gap Size 1e6",
      [&] {
        wrap->SetResolution(48);
        wrap->SetTargetEdgeLength(0);
        wrap->SetGapSize(1e6);
      },
      "Gap Size 1e+06 does not fit in the distance field", false },
    { "Gap Size -1", [&] { wrap->SetGapSize(-1); }, "Gap Size is -1: it must be at least 0",
      false },
    { "Gap Size 1.05", [&] { wrap->SetGapSize(1.05); },
      "Gap Size 1.05 is over half the target's longest side", true },
    { "Edge Length Range 0 1",
      [&] {
        wrap->SetGapSize(0);
        wrap->SetEdgeLengthRange(0, 1);
      },
      "Edge Length Range", false },
    { "Edge Length Range 1 NaN", [&] { wrap->SetEdgeLengthRange(1, kNaN); }, "Edge Length Range",
      false },
    { "Edge Length Range 2 1", [&] { wrap->SetEdgeLengthRange(2, 1); }, "Edge Length Range",
      false },
  };
  for (const auto& c : cases)
  {
    c.set();
    const Said said = whileSaying(wrap, [&] { wrap->Update(); });
    std::cout << c.name << ": " << said.text << std::endl;
    const bool wrapped = wrap->GetOutput()->GetNumberOfPoints() > 0;
    SW_CHECK(said.text.find(c.said) != std::string::npos, c.name << ": says \"" << c.said << "\"");
    SW_CHECK(c.wraps ? (said.errors == 0 && wrapped) : (said.errors > 0 && !wrapped),
      c.name << (c.wraps ? ": a warning and a wrap" : ": an error, empty output"));
  }
  wrap->SetGapSize(0);
  wrap->SetEdgeLengthRange(1, 1);
  wrap->Update();
  SW_CHECK(wrap->GetOutput()->GetNumberOfPoints() > 0 && stepOf(wrap->GetOutput()) == 5,
    "then the defaults wrap");
}

void badDistanceFields()
{
  vtkNew<vtkMeshSignedDistance> sdf;
  sdf->SetInputData(sphere());
  sdf->SetResolution(24);
  sdf->SetOffsetFactor(1.0); // the paper's box, which holds the icosphere of wrapOf
  sdf->Update();
  struct Case
  {
    const char* name;
    std::function<void(vtkImageData*, vtkFloatArray*)> spoil;
  };
  const std::vector<Case> cases = {
    { "shorter than the image",
      [](vtkImageData*, vtkFloatArray* a) { a->SetNumberOfTuples(a->GetNumberOfTuples() / 3); } },
    { "empty", [](vtkImageData*, vtkFloatArray* a) { a->SetNumberOfTuples(0); } },
    { "with a NaN",
      [](vtkImageData*, vtkFloatArray* a) {
        a->SetValue(a->GetNumberOfTuples() / 2, static_cast<float>(kNaN));
      } },
    { "with an infinity",
      [](vtkImageData*, vtkFloatArray* a) { a->SetValue(0, static_cast<float>(kInf)); } },
    { "with no outside (all negative)",
      [](vtkImageData*, vtkFloatArray* a) {
        for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
        {
          a->SetValue(i, -1.0f - std::abs(a->GetValue(i)));
        }
      } },
    { "rotated (a direction matrix)",
      [](vtkImageData* image, vtkFloatArray*) {
        image->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1);
      } },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkImageData> field;
    field->DeepCopy(sdf->GetOutput());
    c.spoil(field, vtkFloatArray::SafeDownCast(field->GetPointData()->GetArray("SignedDistance")));
    auto wrap = wrapOf(sphere());
    wrap->SetInputData(1, field);
    const Said said = whileSaying(wrap, [&] { wrap->Update(); });
    std::cout << "DistanceField " << c.name << ": " << said.text.substr(said.text.find("): ") + 3)
              << std::endl;
    SW_CHECK(said.errors > 0 && wrap->GetOutput()->GetNumberOfPoints() == 0,
      "a DistanceField " << c.name << ": an error and an empty output");
    livesOn(wrap, c.name);
  }
  // No inside (an unsigned field): said, and wrapped as unsigned.
  vtkNew<vtkImageData> field;
  field->DeepCopy(sdf->GetOutput());
  auto* values = vtkFloatArray::SafeDownCast(field->GetPointData()->GetArray("SignedDistance"));
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, std::abs(values->GetValue(i)));
  }
  auto wrap = wrapOf(sphere());
  wrap->SetInputData(1, field);
  const Said said = whileSaying(wrap, [&] { wrap->Update(); });
  std::cout << "DistanceField with no inside: " << said.text << std::endl;
  SW_CHECK(said.errors == 0 && said.text.find("no inside") != std::string::npos &&
      wrap->GetOutput()->GetNumberOfPoints() > 0,
    "a DistanceField with no inside: a warning, and a wrap");
}

void coordinatesTooLarge()
{
  for (double scale : { 1e160, 1e200, 1e300 })
  {
    vtkNew<vtkTransform> transform;
    transform->Scale(scale, scale, scale);
    vtkNew<vtkTransformPolyDataFilter> far;
    far->SetInputData(sphere());
    far->SetTransform(transform);
    far->Update();
    vtkNew<vtkMeshSignedDistance> sdf;
    sdf->SetInputData(far->GetOutput());
    sdf->SetResolution(24);
    Said said = whileSaying(sdf, [&] { sdf->Update(); });
    SW_CHECK(said.errors > 0 && sdf->GetOutput()->GetNumberOfPoints() == 0,
      "a mesh scaled by " << scale << ": Mesh Signed Distance refuses it");
    auto wrap = wrapOf(far->GetOutput());
    said = whileSaying(wrap, [&] { wrap->Update(); });
    SW_CHECK(said.errors > 0 && wrap->GetOutput()->GetNumberOfPoints() == 0,
      "a mesh scaled by " << scale << ": Shrink Wrap refuses it");
    livesOn(wrap, "scaled by " + std::to_string(scale));

    // A mesh far away from an explicit grid at the origin: refused, not a heap overflow.
    sdf->UseExplicitGridOn();
    sdf->SetOutputBounds(-1, 1, -1, 1, -1, 1);
    sdf->SetOutputDimensions(8, 8, 8);
    said = whileSaying(sdf, [&] { sdf->Update(); });
    SW_CHECK(said.errors > 0 && sdf->GetOutput()->GetNumberOfPoints() == 0,
      "a mesh scaled by " << scale << " and an explicit grid at the origin: refused");
  }
  for (double offset : { 1e30, 1e300 })
  {
    vtkNew<vtkMeshSignedDistance> sdf;
    sdf->SetInputData(sphere());
    sdf->SetResolution(24);
    sdf->SetOffsetFactor(offset);
    const Said said = whileSaying(sdf, [&] { sdf->Update(); });
    SW_CHECK(said.errors > 0 && sdf->GetOutput()->GetNumberOfPoints() == 0,
      "Offset Factor " << offset << ": refused");
  }
}

// An abort ends that run only: Mesh Signed Distance computes again after a change; Shrink Wrap does
// not run again by itself, and resumes from its cache when another time is asked for.
void aborts()
{
  // Aborted once, as a user would (the executive's closing progress event must not abort again).
  struct Count
  {
    int events = 0, abortAt = 1;
    double from = 0; // counts the events from this progress on (Shrink Wrap's steps: kSetupShare)
  } count;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&count);
  onProgress->SetCallback([](vtkObject* caller, unsigned long, void* data, void* amount) {
    auto* c = static_cast<Count*>(data);
    if (*static_cast<double*>(amount) >= c->from && ++c->events == c->abortAt)
    {
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  });
  vtkNew<vtkMeshSignedDistance> sdf;
  sdf->SetInputData(sphere());
  sdf->SetResolution(24);
  sdf->AddObserver(vtkCommand::ProgressEvent, onProgress);
  whileSaying(sdf, [&] { sdf->Update(); });
  SW_CHECK(
    sdf->GetOutput()->GetNumberOfPoints() == 0, "Mesh Signed Distance aborted: an empty output");
  sdf->SetResolution(20);
  sdf->Update();
  SW_CHECK(
    sdf->GetOutput()->GetNumberOfPoints() == 21 * 21 * 21, "after a change it computes again");

  auto wrap = wrapOf(sphere(), 30);
  // Aborted at the first event past a sixth of the steps' share (steps ask within themselves too).
  count = { 0, 1, vtkShrinkWrapFilter::kSetupShare + (1 - vtkShrinkWrapFilter::kSetupShare) / 6 };
  wrap->AddObserver(vtkCommand::ProgressEvent, onProgress);
  whileSaying(wrap, [&] { wrap->UpdateTimeStep(30 * 0.015); });
  const int aborted = wrap->GetNumberOfComputedSteps();
  SW_CHECK(wrap->GetOutput()->GetNumberOfPoints() == 0 && aborted > 0 && aborted < 30,
    "Shrink Wrap aborted after " << aborted << " steps: an empty output");
  wrap->UpdateTimeStep(30 * 0.015);
  wrap->Update();
  SW_CHECK(
    wrap->GetNumberOfComputedSteps() == aborted && wrap->GetOutput()->GetNumberOfPoints() == 0,
    "the same request again (a render) does not run the rest (" << wrap->GetNumberOfComputedSteps()
                                                                << " steps)");
  wrap->UpdateTimeStep((aborted - 1) * 0.015);
  SW_CHECK(stepOf(wrap->GetOutput()) == aborted - 1 && wrap->GetNumberOfComputedSteps() == aborted,
    "a step before the abort comes from the cache (" << wrap->GetNumberOfComputedSteps()
                                                     << " computed)");
  wrap->UpdateTimeStep(25 * 0.015);
  SW_CHECK(stepOf(wrap->GetOutput()) == 25 && wrap->GetNumberOfComputedSteps() == 25,
    "a later one resumes from the cached steps (" << wrap->GetNumberOfComputedSteps()
                                                  << " computed)");
  wrap->SetAdvectionSpeed(1.5);
  wrap->UpdateTimeStep(30 * 0.015);
  SW_CHECK(stepOf(wrap->GetOutput()) == 30 && wrap->GetNumberOfComputedSteps() == 30,
    "a change runs normally");
}

// A target whose vertex and line cells name points that do not exist (ids past the end, negative):
// the wrap does not use such cells (a polygon naming one is refused), and Target Measured keeps
// them with the share of the points they do name (none: 0).
void cellsNamingNoPoint()
{
  vtkSmartPointer<vtkPolyData> target = sphere();
  const vtkIdType n = target->GetNumberOfPoints();
  vtkNew<vtkCellArray> verts, lines;
  const vtkIdType vert[] = { vtkIdType(1) << 40 }, line[] = { 0, -7, n };
  verts->InsertNextCell(1, vert);
  lines->InsertNextCell(3, line);
  target->SetVerts(verts);
  target->SetLines(lines);
  auto wrap = wrapOf(target);
  const Said said = whileSaying(wrap, [&] { wrap->Update(); });
  std::cout << "Cells naming no point: " << said.text << std::endl;
  SW_CHECK(wrap->GetOutput()->GetNumberOfPoints() == 162, "cells naming no point: the wrap");
  auto* measured = vtkPolyData::SafeDownCast(wrap->GetOutputDataObject(1));
  vtkDataArray* far = measured ? measured->GetCellData()->GetArray("FarFromWrap") : nullptr;
  SW_CHECK(far && far->GetNumberOfTuples() == target->GetNumberOfCells(),
    "cells naming no point: FarFromWrap on every cell of Target Measured");
  bool shares = far != nullptr;
  for (vtkIdType c = 0; far && c < far->GetNumberOfTuples(); ++c)
  {
    shares = shares && far->GetTuple1(c) >= 0 && far->GetTuple1(c) <= 1;
  }
  SW_CHECK(shares && far->GetTuple1(0) == 0,
    "cells naming no point: every share within [0, 1], the vertex naming none 0");
  livesOn(wrap, "cells naming no point");
}
} // namespace

int TestShrinkWrapBadInput(int, char*[])
{
  compositeInputs();
  compositeTimeSteps();
  starvedCache();
  corruptStartingSurfaces();
  absurdStepsAndTimes();
  absurdSizes();
  badDistanceFields();
  coordinatesTooLarge();
  aborts();
  cellsNamingNoPoint();
  return testing::finish("TestShrinkWrapBadInput");
}
