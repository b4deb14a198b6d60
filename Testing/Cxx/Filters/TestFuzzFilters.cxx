// A bounded fuzz run of both filters: random meshes (ids out of range, NaN and infinite points,
// huge and tiny scales, degenerate and non-manifold triangles, polygons, strips, lines,
// composites), random property values, random distance fields and starting surfaces, random request
// times and aborts. The same two filter objects take every case, so state left behind by one case
// meets the next. Every output must be empty or valid (finite points, ids in range, a full finite
// field), and every tenth case a good input must still give a good output. A crash or a sanitizer
// report fails the test.
//
// Usage: ShrinkWrapCxxTests TestFuzzFilters [seconds=30] [seed=1] [first case=0]
// Each case k is made from (seed, k) alone: "case k" in the output replays with first case = k.
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <random>

namespace
{
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

class Dice
{
public:
  explicit Dice(std::uint64_t seed)
    : Engine(seed)
  {
  }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(this->Engine) < p; }
  int between(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(this->Engine); }
  double uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(this->Engine);
  }
  template <typename T>
  T pick(std::initializer_list<T> values)
  {
    return *(values.begin() + this->between(0, static_cast<int>(values.size()) - 1));
  }
  // A value that is usually sane, sometimes absurd.
  double value(double sane)
  {
    return this->chance(0.95) ? sane
                              : this->pick({ 0.0, -sane, 1e-12, 1e12, 1e300, kNaN, kInf, -kInf });
  }

private:
  std::mt19937_64 Engine;
};

vtkSmartPointer<vtkPolyData> sphere(double radius = 1)
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(radius);
  source->SetThetaResolution(12);
  source->SetPhiResolution(12);
  source->Update();
  return source->GetOutput();
}

// Now and then, one of the targets that once gave wrong results: the triangles reversed (facing
// in), every triangle twice (double-sided), or "sand" (up to 300 tiny disjoint tetrahedra in a
// cube of the mesh's scale).
void addFamily(Dice& dice, double scale, double shift, vtkPoints* points, vtkCellArray* polys)
{
  const int family = dice.chance(0.3) ? dice.between(0, 2) : -1;
  if ((family == 0 || family == 1) && polys->GetNumberOfCells() > 0)
  {
    vtkNew<vtkCellArray> turned;
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
    {
      polys->GetCellAtId(c, ids);
      std::vector<vtkIdType> reversed(ids->begin(), ids->end());
      std::reverse(reversed.begin(), reversed.end());
      turned->InsertNextCell(static_cast<vtkIdType>(reversed.size()), reversed.data());
    }
    if (family == 1)
    {
      turned->Append(polys);
    }
    polys->DeepCopy(turned);
  }
  else if (family == 2)
  {
    const int grains = dice.between(1, 300);
    const double size = 0.01 * scale;
    for (int g = 0; g < grains; ++g)
    {
      const vtkIdType first = points->GetNumberOfPoints();
      const double x = scale * dice.uniform(-1, 1) + shift, y = scale * dice.uniform(-1, 1),
                   z = scale * dice.uniform(-1, 1);
      points->InsertNextPoint(x, y, z);
      points->InsertNextPoint(x + size, y, z);
      points->InsertNextPoint(x, y + size, z);
      points->InsertNextPoint(x, y, z + size);
      const vtkIdType faces[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
      for (const auto& f : faces)
      {
        const vtkIdType t[3] = { first + f[0], first + f[1], first + f[2] };
        polys->InsertNextCell(3, t);
      }
    }
  }
}

// A mesh: a sphere or random points, with cells of every kind, some of them broken.
vtkSmartPointer<vtkPolyData> randomMesh(Dice& dice)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  if (dice.chance(0.05))
  {
    return mesh; // empty
  }
  const double scale =
    dice.chance(0.8) ? dice.uniform(0.1, 10) : std::pow(10.0, dice.between(-40, 200));
  const double shift = dice.chance(0.8) ? 0 : std::pow(10.0, dice.between(0, 200));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys, strips, lines, verts;
  if (dice.chance(0.5))
  {
    vtkSmartPointer<vtkPolyData> s = sphere();
    for (vtkIdType i = 0; i < s->GetNumberOfPoints(); ++i)
    {
      double x[3];
      s->GetPoint(i, x);
      const double jitter = dice.chance(0.3) ? 0.2 : 0;
      points->InsertNextPoint(scale * (x[0] + dice.uniform(-jitter, jitter + 1e-300)) + shift,
        scale * x[1], scale * x[2]);
    }
    polys->DeepCopy(s->GetPolys());
  }
  else
  {
    const int n = dice.between(1, 40);
    for (int i = 0; i < n; ++i)
    {
      points->InsertNextPoint(scale * dice.uniform(-1, 1) + shift, scale * dice.uniform(-1, 1),
        scale * dice.uniform(-1, 1));
    }
  }
  addFamily(dice, scale, shift, points, polys);
  const vtkIdType np = points->GetNumberOfPoints();
  auto id = [&]() -> vtkIdType {
    return dice.chance(0.01)
      ? dice.pick<vtkIdType>({ -1, np, np + 1000, std::numeric_limits<int>::max() })
      : dice.between(0, static_cast<int>(np) - 1);
  };
  const int extra = dice.between(0, 30);
  for (int c = 0; c < extra; ++c)
  {
    std::vector<vtkIdType> ids(dice.between(1, 8));
    for (auto& i : ids)
    {
      i = id();
    }
    const int kind = dice.between(0, 9);
    vtkCellArray* cells =
      kind < 7 ? polys.Get() : (kind == 7 ? strips.Get() : (kind == 8 ? lines.Get() : verts.Get()));
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  if (dice.chance(0.03))
  {
    points->SetPoint(
      dice.between(0, static_cast<int>(np) - 1), dice.pick({ kNaN, kInf, -kInf }), 0, 0);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);
  mesh->SetLines(lines);
  mesh->SetVerts(verts);
  return mesh;
}

// A target: a mesh, or now and then a composite of meshes (and a block that is not a mesh).
vtkSmartPointer<vtkDataObject> randomTarget(Dice& dice)
{
  if (dice.chance(0.85))
  {
    return randomMesh(dice);
  }
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  const int n = dice.between(0, 3);
  for (int b = 0; b < n; ++b)
  {
    blocks->SetBlock(b, randomMesh(dice));
  }
  if (dice.chance(0.3))
  {
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(sphere()->GetPoints());
    const vtkIdType tet[4] = { 0, 1, 2, 3 };
    grid->InsertNextCell(VTK_TETRA, 4, tet);
    blocks->SetBlock(n, grid);
  }
  return blocks;
}

void randomizeDistance(vtkMeshSignedDistance* f, Dice& dice)
{
  f->SetResolution(dice.chance(0.9) ? dice.between(1, 40) : dice.pick({ -5, 0, 1 << 20 }));
  // A sane cell size for a mesh of unknown scale can mean a billion nodes: only absurd ones here.
  f->SetCellSize(dice.chance(0.8) ? 0 : dice.pick({ -1.0, 1e-12, 1e300, kNaN, kInf }));
  f->SetBoxScale(dice.value(1.1));
  f->SetOffsetFactor(dice.value(1.0));
  f->SetUseExplicitGrid(dice.chance(0.15));
  f->SetOutputBounds(
    dice.value(-2), dice.value(2), dice.value(-2), dice.value(2), dice.value(-2), dice.value(2));
  f->SetOutputDimensions(
    dice.between(-2, 20), dice.between(-2, 20), dice.chance(0.95) ? dice.between(-2, 20) : 1 << 30);
  f->SetSweepMethod(dice.between(0, 1));
  f->SetBandLayers(dice.between(-2, 3));
  f->SetComputeSign(dice.chance(0.8));
}

void randomizeWrap(vtkShrinkWrapFilter* f, Dice& dice)
{
  f->SetTimePerStep(dice.value(0.015));
  f->SetNumberOfSteps(
    dice.chance(0.9) ? dice.between(-2, 12) : dice.pick({ 1000, std::numeric_limits<int>::max() }));
  f->SetSubdivisionLevel(dice.chance(0.9) ? dice.between(0, 2) : dice.pick({ -1, 3, 9 }));
  f->SetSmoothing(dice.value(1));
  f->SetSmoothingFalloff(dice.value(1));
  f->SetAdvectionSpeed(dice.value(1));
  f->SetConcavityPush(dice.chance(0.5) ? 0 : dice.value(0.5));
  f->SetTangentialRedistribution(dice.between(-1, 3));
  f->SetAngleWeight(dice.value(0.5));
  f->SetVolumeWeight(dice.value(1));
  f->SetDistanceWeightAmplitude(dice.value(1));
  f->SetDistanceWeighting(dice.chance(0.3));
  f->SetEdgeFlips(dice.chance(0.7));
  f->SetEdgeCollapses(dice.chance(0.7));
  f->SetCoverRims(dice.chance(0.7));
  f->SetFitFacets(dice.chance(0.7));
  f->SetFlipDihedralLimit(dice.value(60));
  f->SetStartingShape(dice.between(0, 1));
  f->SetStartOffsetInCells(dice.value(3));
  f->SetGapSize(dice.chance(0.5) ? 0 : dice.value(0.2));
  f->SetRemeshing(dice.chance(0.7));
  // Coarse (a few hundred vertices on the unit sphere): the fuzz runs up to 10,000 steps under
  // ASan.
  f->SetTargetEdgeLength(dice.value(0.4));
  f->SetEdgeLengthRange(
    dice.chance(0.5) ? 1 : dice.value(0.6), dice.chance(0.5) ? 1 : dice.value(1.6));
  f->SetInitialRelaxation(dice.between(-1, 12));
  f->SetAutomaticScaling(dice.chance(0.8));
  f->SetSolverTolerance(dice.value(1e-6));
  f->SetResolution(dice.chance(0.9) ? dice.between(-1, 32) : 1 << 20);
  f->SetCacheMemoryMiB(dice.chance(0.7) ? 512 : dice.pick({ 0.0, 1e-9, 0.01, -1.0, kNaN }));
  f->SetTimeMode(dice.chance(0.8) ? vtkShrinkWrapFilter::TIME_AUTOMATIC : dice.between(-1, 3));
}

// An image for the DistanceField port: a real field, or random values, short arrays, NaNs.
vtkSmartPointer<vtkImageData> randomField(Dice& dice, vtkMeshSignedDistance* distance)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  if (dice.chance(0.5))
  {
    image->DeepCopy(distance->GetOutput());
  }
  else
  {
    image->SetDimensions(dice.between(0, 8), dice.between(0, 8), dice.between(0, 8));
    image->SetSpacing(dice.value(0.5), dice.value(0.5), dice.value(0.5));
    image->SetOrigin(-2, -2, -2);
    vtkNew<vtkFloatArray> values;
    values->SetName("SignedDistance");
    values->SetNumberOfTuples(image->GetNumberOfPoints());
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      values->SetValue(i, static_cast<float>(dice.value(dice.uniform(-1, 3))));
    }
    image->GetPointData()->AddArray(values);
  }
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  if (values && values->GetNumberOfTuples() > 0 && dice.chance(0.2))
  {
    values->SetNumberOfTuples(dice.between(0, static_cast<int>(values->GetNumberOfTuples()) - 1));
  }
  return image;
}

// An empty output, or a surface of triangles with finite points and valid ids.
bool validMesh(vtkPolyData* mesh)
{
  shrinkwrap::TriangleSoup surface;
  return mesh->GetNumberOfCells() == 0 || shrinkwrap::convert::surfaceOf(mesh, surface);
}

bool validWrap(vtkDataObject* output)
{
  for (vtkPolyData* mesh : vtkCompositeDataSet::GetDataSets<vtkPolyData>(output))
  {
    if (!validMesh(mesh))
    {
      return false;
    }
  }
  return true;
}

// The enclosed volume and the area of a closed triangle surface.
std::pair<double, double> volumeAndArea(vtkPolyData* mesh)
{
  double volume = 0, area = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() != 3)
    {
      continue;
    }
    double a[3], b[3], d[3];
    mesh->GetPoint(ids->GetId(0), a);
    mesh->GetPoint(ids->GetId(1), b);
    mesh->GetPoint(ids->GetId(2), d);
    const shrinkwrap::Vec3 p(a[0], a[1], a[2]), q(b[0], b[1], b[2]), r(d[0], d[1], d[2]);
    volume += p.dot(q.cross(r)) / 6;
    area += 0.5 * (q - p).cross(r - p).norm();
  }
  return { volume, area };
}

// A wrap whose last step says "ok" has landed: 95% of its vertices within 1.5 cells of the field
// (its Distance array against its FieldCellSize), or it rests there (its last step moved it by
// under 0.02 cells on average, from the volumes of the two last steps' outputs, asked for again);
// else its Status says it has not landed, or failed.
bool landedOrSaysSo(vtkShrinkWrapFilter* wrap, int steps)
{
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(wrap->GetOutputDataObject(0));
  if (!mesh || mesh->GetNumberOfPoints() == 0 || steps < 1)
  {
    return true; // a composite's blocks, an empty output: nothing claimed
  }
  auto* status = vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("Status"));
  vtkDataArray* step = mesh->GetFieldData()->GetArray("StepIndex");
  vtkDataArray* cell = mesh->GetFieldData()->GetArray("FieldCellSize");
  vtkDataArray* distance = mesh->GetPointData()->GetArray("Distance");
  if (!status || !step || !cell || !distance || status->GetValue(0) != "ok" ||
    step->GetTuple1(0) != steps)
  {
    return true;
  }
  std::vector<double> d(distance->GetNumberOfTuples());
  for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
  {
    d[i] = std::abs(distance->GetTuple1(i));
  }
  std::sort(d.begin(), d.end());
  const double h = cell->GetTuple1(0);
  if (d[static_cast<std::size_t>(0.95 * (d.size() - 1))] <= 1.5 * h)
  {
    return true;
  }
  const auto last = volumeAndArea(mesh);
  wrap->UpdateTimeStep((steps - 1) * wrap->GetTimePerStep());
  vtkPolyData* before = vtkPolyData::SafeDownCast(wrap->GetOutputDataObject(0));
  const auto previous = before ? volumeAndArea(before) : std::make_pair(0.0, 0.0);
  wrap->UpdateTimeStep(steps * wrap->GetTimePerStep());
  return last.second > 0 && std::abs(last.first - previous.first) / (last.second * h) < 0.02;
}

bool validField(vtkImageData* image)
{
  if (image->GetNumberOfPoints() == 0)
  {
    return true;
  }
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  if (!values || values->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    if (!std::isfinite(values->GetValue(i)))
    {
      return false;
    }
  }
  return true;
}

// Aborts at a chosen progress event (0: never).
struct AbortPlan
{
  int events = 0, at = 0;
};

void abortAt(vtkObject* caller, unsigned long, void* data, void*)
{
  auto* plan = static_cast<AbortPlan*>(data);
  if (++plan->events == plan->at)
  {
    static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
  }
}
} // namespace

int TestFuzzFilters(int argc, char* argv[])
{
  const double seconds = argc > 1 ? std::atof(argv[1]) : 30;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const int first = argc > 3 ? std::atoi(argv[3]) : 0;
  vtkObject::GlobalWarningDisplayOff(); // thousands of expected errors

  vtkNew<vtkMeshSignedDistance> distance;
  vtkNew<vtkShrinkWrapFilter> wrap;
  AbortPlan distancePlan, wrapPlan;
  vtkNew<vtkCallbackCommand> distanceAbort, wrapAbort;
  distanceAbort->SetCallback(abortAt);
  distanceAbort->SetClientData(&distancePlan);
  wrapAbort->SetCallback(abortAt);
  wrapAbort->SetClientData(&wrapPlan);
  distance->AddObserver(vtkCommand::ProgressEvent, distanceAbort);
  wrap->AddObserver(vtkCommand::ProgressEvent, wrapAbort);

  const auto start = std::chrono::steady_clock::now();
  int cases = 0, fields = 0, wraps = 0;
  for (int k = first;
       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds;
       ++k)
  {
    Dice dice(seed * 1000003u + static_cast<std::uint64_t>(k));
    std::cout << "case " << k << std::endl; // the last one printed is the one that crashed
    ++cases;

    vtkSmartPointer<vtkDataObject> target = randomTarget(dice);
    randomizeDistance(distance, dice);
    distance->SetInputData(target);
    distancePlan = { 0, dice.chance(0.1) ? dice.between(1, 5) : 0 };
    distance->Update();
    SW_CHECK(validField(distance->GetOutput()),
      "case " << k << ": Mesh Signed Distance gives a valid or empty field");
    fields += distance->GetOutput()->GetNumberOfPoints() > 0;

    randomizeWrap(wrap, dice);
    wrap->SetInputData(0, dice.chance(0.9) ? target : vtkSmartPointer<vtkDataObject>(sphere()));
    wrap->SetInputData(1, dice.chance(0.3) ? randomField(dice, distance) : nullptr);
    wrap->SetInputData(2, dice.chance(0.2) ? randomMesh(dice) : nullptr);
    wrapPlan = { 0, dice.chance(0.1) ? dice.between(1, 10) : 0 };
    const int steps = wrap->GetNumberOfSteps();
    for (int request = dice.between(1, 3); request > 0; --request)
    {
      const double tau = wrap->GetTimePerStep();
      // Times past the end, but no more than 20 steps' work when there are thousands.
      const double t = steps > 20
        ? tau * dice.between(-2, 20)
        : dice.pick({ 0.0, tau * dice.between(-3, 15), kNaN, kInf, -kInf, 1e9, -1e300 });
      if (steps <= 20 && dice.chance(0.2))
      {
        wrap->Update(); // no time asked: the last step
      }
      else
      {
        wrap->UpdateTimeStep(t);
      }
      SW_CHECK(validWrap(wrap->GetOutputDataObject(0)),
        "case " << k << ": Shrink Wrap gives a valid or empty surface");
      SW_CHECK(landedOrSaysSo(wrap, steps),
        "case " << k << ": a wrap reported ok at its last step has landed");
      wraps +=
        !vtkCompositeDataSet::GetDataSets<vtkPolyData>(wrap->GetOutputDataObject(0)).empty() &&
        vtkCompositeDataSet::GetDataSets<vtkPolyData>(wrap->GetOutputDataObject(0))[0]
            ->GetNumberOfPoints() > 0;
    }

    if (k % 10 == 9) // the same filters still work on a good input with sane settings
    {
      // An abort asked for at the closing progress event of the last run is one for the next run.
      wrapPlan = { 0, 0 };
      distancePlan = { 0, 0 };
      wrap->AbortExecuteOff();
      distance->AbortExecuteOff();
      distance->SetInputData(sphere());
      distance->SetResolution(16);
      distance->SetCellSize(0);
      distance->SetBoxScale(1.1);
      distance->SetOffsetFactor(1);
      distance->SetUseExplicitGrid(false);
      distance->SetBandLayers(1);
      distance->SetComputeSign(true);
      distance->Update();
      SW_CHECK(distance->GetOutput()->GetNumberOfPoints() > 0 && validField(distance->GetOutput()),
        "case " << k << ": Mesh Signed Distance lives on");
      wrap->SetInputData(0, sphere());
      wrap->SetInputData(1, nullptr);
      wrap->SetInputData(2, nullptr);
      wrap->SetTimePerStep(0.015);
      wrap->SetNumberOfSteps(3);
      wrap->SetSubdivisionLevel(2);
      wrap->SetSmoothing(1);
      wrap->SetSmoothingFalloff(1);
      wrap->SetAdvectionSpeed(1);
      wrap->SetConcavityPush(0);
      wrap->SetTangentialRedistribution(vtkShrinkWrapFilter::ANGLE);
      wrap->SetAngleWeight(0.5);
      wrap->SetVolumeWeight(1);
      wrap->SetDistanceWeightAmplitude(1);
      wrap->SetFlipDihedralLimit(60);
      wrap->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
      wrap->SetRemeshing(false); // 162 vertices throughout
      wrap->SetGapSize(0);
      wrap->SetTargetEdgeLength(0);
      wrap->SetEdgeLengthRange(1, 1);
      wrap->SetInitialRelaxation(10);
      wrap->SetAutomaticScaling(true);
      wrap->SetSolverTolerance(1e-6);
      wrap->SetResolution(24);
      wrap->SetCacheMemoryMiB(512);
      wrap->SetStartOffsetInCells(3);
      wrap->SetTimeMode(vtkShrinkWrapFilter::TIME_AUTOMATIC);
      wrap->Update();
      SW_CHECK(wrap->GetOutput() && wrap->GetOutput()->GetNumberOfPoints() == 162 &&
          validWrap(wrap->GetOutput()),
        "case " << k << ": Shrink Wrap lives on");
    }
  }
  std::cout << cases << " cases from seed " << seed << " in " << seconds << " s: " << fields
            << " non-empty fields, " << wraps << " non-empty wraps" << std::endl;
  SW_CHECK(cases >= 10, "at least ten cases ran");
  return testing::finish("TestFuzzFilters");
}
