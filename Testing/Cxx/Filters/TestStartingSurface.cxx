// A contour of the distance field as the starting surface (the paper's Section 5: "start the
// evolution by generating a contour surface of distance function d ... after tangentially relaxing
// triangle vertices", so that the holes of a target of higher genus stay open):
// - relaxTangentially turns a marching-cubes contour's slivers into good triangles, keeps it closed
//   and keeps its vertices near the level set;
// - the filter wraps a torus from a contour, keeping the hole (Euler characteristic 0) where the
//   icosphere closes it over (2), and starts from the relaxed contour;
// - the Offset Surface start (the default) does the same by itself, and closes the hole over when
// it is
//   narrower than the Gap Size; with remeshing on, it begins coarsened to the Target Edge Length;
// - asked for fewer joins, a contour is taken of the grid with the shallower corner raised where
// the
//   case table joins the corners below the value on an ambiguous face that the trilinear
//   interpolant keeps apart (as many blobs as at half the spacing, the grid's number of triangles),
//   not where the raise would change the interpolant's topology, also where the join takes two
//   faces (each raise alone undoes nothing), and the grid is left alone elsewhere
//   (ContourTopology.h);
// - the core's triangle counts per case are those of VTK's marching-cubes table, which the filters'
//   contour uses;
// - where the offset start joins two parts across a slit the field keeps open (a handle), a lower
//   offset without that handle is taken.
#include "Distance/ContourTopology.h"
#include "Evolution/StartingSurface.h"
#include "Remeshing/Relaxation.h"
#include "Surface/Components.h"
#include "Surface/Icosphere.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkAppendPolyData.h>
#include <vtkCellData.h>
#include <vtkContourFilter.h>
#include <vtkFieldData.h>
#include <vtkMarchingCubesTriangleCases.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>

#include <algorithm>

namespace
{
using shrinkwrap::Vec3;

constexpr double R = 1.0, r = 0.35; // the torus: ring radius and tube radius

double torusDistance(const Vec3& p)
{
  return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r;
}

// A closed triangulated torus, nu x nv quads split in two.
vtkSmartPointer<vtkPolyData> torus(int nu = 96, int nv = 32)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      points->InsertNextPoint(
        (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  }
  vtkNew<vtkCellArray> triangles;
  const auto id = [nu, nv](int i, int j) { return static_cast<vtkIdType>((i % nu) * nv + j % nv); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const vtkIdType a[3] = { id(i, j), id(i + 1, j), id(i + 1, j + 1) };
      const vtkIdType b[3] = { id(i, j), id(i + 1, j + 1), id(i, j + 1) };
      triangles->InsertNextCell(3, a);
      triangles->InsertNextCell(3, b);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}

// The surface of a vtkPolyData of triangles.
shrinkwrap::TriangleSoup surfaceOf(vtkPolyData* mesh)
{
  return testing::triangulated(mesh);
}

std::string statusOf(vtkPolyData* mesh)
{
  auto status = vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("Status"));
  return status ? status->GetValue(0) : std::string();
}

// The level set d = 0.1 of the torus, sampled on a 0.05 grid, by marching cubes.
vtkSmartPointer<vtkPolyData> torusContour(double level, double h)
{
  vtkNew<vtkImageData> grid;
  const int n[3] = { static_cast<int>(2 * (R + r + 0.3) / h) + 1, n[0],
    static_cast<int>(2 * (r + 0.3) / h) + 1 };
  grid->SetDimensions(n[0], n[1], n[2]);
  grid->SetSpacing(h, h, h);
  grid->SetOrigin(-(n[0] - 1) * h / 2, -(n[1] - 1) * h / 2, -(n[2] - 1) * h / 2);
  vtkNew<vtkFloatArray> d;
  d->SetName("d");
  d->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    Vec3 p;
    grid->GetPoint(i, p.data());
    d->SetValue(i, static_cast<float>(torusDistance(p)));
  }
  grid->GetPointData()->SetScalars(d);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, level);
  contour->Update();
  return contour->GetOutput();
}

void relaxesAContour()
{
  const double h = 0.05, level = 0.1;
  shrinkwrap::TriangleSoup s = surfaceOf(torusContour(level, h));
  shrinkwrap::SurfaceMesh mesh;
  std::string error;
  SW_CHECK(testing::builds(s.points, s.triangles, mesh, error), "the contour is closed: " << error);
  const double before = shrinkwrap::smallestAngle(mesh, s.points).angle;
  shrinkwrap::SurfaceMesh relaxed = mesh;
  shrinkwrap::relaxTangentially(relaxed, shrinkwrap::RelaxSettings());
  const std::vector<Vec3>& x = relaxed.points();
  const double after = shrinkwrap::smallestAngle(relaxed, x).angle;
  double drift = 0;
  for (const Vec3& p : x)
  {
    drift = std::max(drift, std::abs(torusDistance(p) - level));
  }
  std::cout << "contour of " << s.points.size() << " vertices: smallest angle "
            << before * 180 / M_PI << " -> " << after * 180 / M_PI
            << " degrees; largest drift off the level set " << drift / h << " h" << std::endl;
  SW_CHECK(before < 1 * M_PI / 180, "marching cubes leaves slivers");
  SW_CHECK(after > 15 * M_PI / 180, "relaxed: no triangle angle below 15 degrees");
  SW_CHECK(drift < 0.1 * h, "the relaxed vertices stay within 0.1 h of the level set");
  SW_CHECK(relaxed.vertexCount() == mesh.vertexCount(), "no vertex added or lost");
}

int eulerCharacteristic(vtkPolyData* surface)
{
  return static_cast<int>(surface->GetNumberOfPoints() - surface->GetNumberOfCells() / 2);
}

void wrapsATorusFromAContour()
{
  vtkSmartPointer<vtkPolyData> target = torus();
  vtkNew<vtkMeshSignedDistance> field;
  field->SetInputData(target);
  field->SetResolution(60);
  field->SetOffsetFactor(1.0); // the paper's box, which holds the icosphere below
  field->Update();
  const double h = field->GetOutput()->GetSpacing()[0];
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(field->GetOutputPort());
  contour->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "SignedDistance");
  contour->SetValue(0, 3 * h);

  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(target);
  wrap->SetDistanceFieldConnection(field->GetOutputPort());
  wrap->SetInitialSurfaceConnection(contour->GetOutputPort());
  wrap->Update();
  vtkPolyData* out = wrap->GetOutput();
  vtkDataArray* distance = out->GetPointData()->GetArray("Distance");
  std::vector<double> d;
  for (vtkIdType i = 0; distance && i < distance->GetNumberOfTuples(); ++i)
  {
    d.push_back(std::abs(distance->GetTuple1(i)));
  }
  std::sort(d.begin(), d.end());
  const double median = d.empty() ? 1e9 : d[d.size() / 2];
  std::cout << "torus from a contour at 3 h: " << statusOf(out) << ", " << out->GetNumberOfPoints()
            << " vertices, Euler characteristic " << eulerCharacteristic(out) << ", median |d| "
            << median / h << " h" << std::endl;
  SW_CHECK(statusOf(out) == "ok", "200 steps from the contour");
  SW_CHECK(eulerCharacteristic(out) == 0, "the hole stays open");
  SW_CHECK(median < 0.25 * h, "the wrap lies on the torus (median |d| < h / 4)");

  vtkNew<vtkShrinkWrapFilter> sphere;
  sphere->SetInputData(target);
  sphere->SetDistanceFieldConnection(field->GetOutputPort());
  sphere->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
  sphere->SetRemeshing(false);
  sphere->Update();
  SW_CHECK(
    eulerCharacteristic(sphere->GetOutput()) == 2, "from the icosphere the hole is spanned over");

  // Step 0 is the relaxed contour; with InitialRelaxation 0, the contour as given (with its
  // slivers).
  const auto smallestAngleAtStart = [&wrap] {
    wrap->UpdateTimeStep(0);
    vtkDataArray* angles = wrap->GetOutput()->GetCellData()->GetArray("MinAngle");
    return angles ? angles->GetRange()[0] : -1.0;
  };
  const double relaxed = smallestAngleAtStart();
  wrap->SetInitialRelaxation(0);
  const double given = smallestAngleAtStart();
  std::cout << "smallest angle at step 0: " << given << " degrees as given, " << relaxed
            << " relaxed" << std::endl;
  SW_CHECK(relaxed > 15 && given >= 0 && given < 5,
    "the filter relaxes the InitialSurface before it evolves");
}

// The Offset Surface start (the default) keeps the torus's hole open; a slot narrower than the Gap
// Size is bridged, a wider one is not. (A closing by a ball never bridges a ring's hole: balls from
// both sides cover its middle whatever their size.)
void wrapsATorusFromItsOffset()
{
  vtkSmartPointer<vtkPolyData> target = torus();
  vtkNew<vtkShrinkWrapFilter> wrap;
  wrap->SetInputData(target);
  wrap->Update();
  vtkPolyData* out = wrap->GetOutput();
  vtkDataArray* distance = out->GetPointData()->GetArray("Distance");
  double largest = 0;
  for (vtkIdType i = 0; distance && i < distance->GetNumberOfTuples(); ++i)
  {
    largest = std::max(largest, std::abs(distance->GetTuple1(i)));
  }
  std::cout << "torus from its offset surface: " << statusOf(out) << ", "
            << out->GetNumberOfPoints() << " vertices, Euler characteristic "
            << eulerCharacteristic(out) << ", largest |d| at a vertex " << largest
            << " (tube radius " << r << ")" << std::endl;
  SW_CHECK(statusOf(out) == "ok", "200 steps from the offset surface");
  // 0.03 r is a fraction of a cell of the filter's field (Resolution 80 over 1.25 times the torus).
  SW_CHECK(eulerCharacteristic(out) == 0 && largest < 0.03 * r,
    "the hole stays open, the wrap on the torus");

  // Two spheres of radius 1 with a slot of 0.3 between them.
  vtkNew<vtkSphereSource> left, right;
  left->SetCenter(-1.15, 0, 0);
  right->SetCenter(1.15, 0, 0);
  for (vtkSphereSource* s : { left.Get(), right.Get() })
  {
    s->SetRadius(1);
    s->SetThetaResolution(48);
    s->SetPhiResolution(24);
  }
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(left->GetOutputPort());
  both->AddInputConnection(right->GetOutputPort());
  for (const double gap : { 0.15, 0.6 })
  {
    vtkNew<vtkShrinkWrapFilter> spheres;
    spheres->SetInputConnection(both->GetOutputPort());
    spheres->SetGapSize(gap);
    spheres->SetNumberOfSteps(100);
    spheres->Update();
    vtkNew<vtkPolyDataConnectivityFilter> pieces;
    pieces->SetInputData(spheres->GetOutput());
    pieces->SetExtractionModeToAllRegions();
    pieces->Update();
    const int count = pieces->GetNumberOfExtractedRegions();
    std::cout << "two spheres 0.3 apart, Gap Size " << gap << ": " << statusOf(spheres->GetOutput())
              << ", " << count << " piece(s), Euler characteristic "
              << eulerCharacteristic(spheres->GetOutput()) << std::endl;
    SW_CHECK(statusOf(spheres->GetOutput()) == "ok", "the two spheres wrap");
    const std::string expected = gap < 0.3 ? "a slot wider than the Gap Size stays open"
                                           : "a slot narrower than the Gap Size is bridged";
    SW_CHECK(count == (gap < 0.3 ? 2 : 1), expected);
  }
}

// The offset start is a contour with a vertex every fraction of a cell; with remeshing on, the
// evolution begins from it coarsened to the Target Edge Length (checked against crossings), not at
// the grid's resolution.
void coarsensTheOffsetStart()
{
  vtkSmartPointer<vtkPolyData> target = torus();
  int previous = 0;
  for (const double L : { 0.06, 0.12 })
  {
    vtkNew<vtkShrinkWrapFilter> wrap;
    wrap->SetInputData(target);
    wrap->SetTargetEdgeLength(L);
    wrap->SetNumberOfSteps(0);
    wrap->Update();
    vtkPolyData* start = wrap->GetOutput();
    const shrinkwrap::TriangleSoup s = surfaceOf(start);
    double edges = 0;
    for (const auto& t : s.triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        edges += (s.points[t[k]] - s.points[t[(k + 1) % 3]]).norm();
      }
    }
    const double mean = edges / (3.0 * s.triangles.size());
    const long long crossing = shrinkwrap::findSelfIntersections(s.points, s.triangles).pairs;
    std::cout << "offset start of the torus at L = " << L << ": " << statusOf(start) << ", "
              << s.points.size() << " vertices, mean edge " << mean << ", Euler characteristic "
              << eulerCharacteristic(start) << ", " << crossing << " crossing pairs" << std::endl;
    SW_CHECK(statusOf(start) == "ok" && eulerCharacteristic(start) == 0 && crossing == 0,
      "the coarsened start is a closed torus that does not cross itself");
    SW_CHECK(mean > 0.7 * L && mean < 1.2 * L, "its edges are about L long");
    SW_CHECK(previous == 0 || 2.5 * s.points.size() < previous,
      "twice L: about a quarter of the vertices");
    previous = static_cast<int>(s.points.size());
  }
}

// 7 x 7 x 3 nodes at `outside` but two blocks of 2 x 2 nodes at `below` on the middle layer, (1..2,
// 1..2) and (3..4, 3..4), which meet only at the face (2..3, 2..3): `below` at (2, 2) and (3, 3),
// `outside` at (3, 2) and (2, 3) -- its corners alternate about 0.
shrinkwrap::DistanceGrid ambiguousFace(float below, float outside)
{
  shrinkwrap::GridLattice lattice;
  lattice.dims = { 7, 7, 3 };
  std::vector<float> values(lattice.nodeCount(), outside);
  for (const int corner : { 1, 3 })
  {
    for (int j = corner; j < corner + 2; ++j)
    {
      for (int i = corner; i < corner + 2; ++i)
      {
        values[lattice.index(i, j, 1)] = below;
      }
    }
  }
  return shrinkwrap::DistanceGrid(lattice, std::move(values));
}

long long eulerOf(const shrinkwrap::TriangleSoup& s)
{
  return static_cast<long long>(s.points.size()) - static_cast<long long>(s.triangles.size()) / 2;
}

void countsAsVTKsCaseTable()
{
  const vtkMarchingCubesTriangleCases* cases = vtkMarchingCubesTriangleCases::GetCases();
  int differ = 0;
  for (int c = 0; c < 256; ++c)
  {
    int edges = 0;
    while (edges < 16 && cases[c].edges[edges] >= 0)
    {
      ++edges;
    }
    differ += shrinkwrap::marchingCubesTriangleCounts()[c] != edges / 3;
  }
  SW_CHECK(differ == 0, "the triangle counts of all 256 cases are VTK's (" << differ << " differ)");
}

void followsTheInterpolantsTopology()
{
  using shrinkwrap::contourEulerCharacteristic;
  // -1 and +2: the face's bilinear saddle is +0.5, so the interpolant keeps the two nodes below 0
  // apart (two closed blobs, 4) where the table joins them (one, 2).
  const shrinkwrap::DistanceGrid apart = ambiguousFace(-1, 2);
  SW_CHECK(
    contourEulerCharacteristic(apart, 0).grid == 2, "the table joins the corners below: one blob");
  SW_CHECK(contourEulerCharacteristic(apart, 0).halfSpacing == 4,
    "at half the spacing they are apart: two blobs");
  const shrinkwrap::TriangleSoup split =
    shrinkwrap::contourWithFewerJoins(apart, 0, shrinkwrap::convert::contour);
  const shrinkwrap::TriangleSoup table = shrinkwrap::convert::contour(apart, 0);
  SW_CHECK(eulerOf(split) == 4, "the contour is the two blobs, not one (" << eulerOf(split) << ")");
  SW_CHECK(eulerOf(table) == 2, "unless asked for: the table's one blob");
  SW_CHECK(split.triangles.size() <= table.triangles.size(),
    "from the grid, not at half the spacing: "
      << split.triangles.size() << " triangles (the table's " << table.triangles.size() << ")");
  // Which corner is raised: the shallower of the two below (-0.5 against -1), and only that node.
  const shrinkwrap::DistanceGrid uneven = [] {
    shrinkwrap::DistanceGrid g = ambiguousFace(-1, 2);
    shrinkwrap::FieldValues v = g.values();
    v[g.lattice().index(3, 3, 1)] = -0.5f;
    return shrinkwrap::DistanceGrid(g.lattice(), std::move(v));
  }();
  const shrinkwrap::DistanceGrid separated = shrinkwrap::withFacesSeparated(uneven, 0);
  int changed = 0;
  for (std::int64_t n = 0; n < uneven.lattice().nodeCount(); ++n)
  {
    changed += separated.values()[n] != uneven.values()[n];
  }
  SW_CHECK(changed == 1 && separated.values()[uneven.lattice().index(3, 3, 1)] > 0 &&
      contourEulerCharacteristic(separated, 0).grid == 4,
    "the shallower corner alone is raised above the value (" << changed << " changed): two blobs");
  // Not where the raise would change the interpolant's own topology: with the second block a single
  // node, raising it would delete that blob, which the interpolant has.
  const shrinkwrap::DistanceGrid lone = [&uneven] {
    shrinkwrap::FieldValues v = uneven.values();
    for (const auto& c : { std::array<int, 3>{ 4, 3, 1 }, std::array<int, 3>{ 3, 4, 1 },
           std::array<int, 3>{ 4, 4, 1 } })
    {
      v[uneven.lattice().index(c[0], c[1], c[2])] = 2;
    }
    return shrinkwrap::DistanceGrid(uneven.lattice(), std::move(v));
  }();
  SW_CHECK(contourEulerCharacteristic(lone, 0).halfSpacing == 4 &&
      shrinkwrap::withFacesSeparated(lone, 0).values() == lone.values(),
    "a lone node below is kept: raising it would delete a blob of the interpolant");
  // Two blocks two layers thick meet along an edge, through two ambiguous faces: neither raise
  // alone undoes the join (the other face still makes it), both together do (the hand's thumb took
  // six).
  const shrinkwrap::DistanceGrid edge = [] {
    shrinkwrap::GridLattice lattice;
    lattice.dims = { 7, 7, 4 };
    std::vector<float> v(lattice.nodeCount(), 2);
    for (int k = 1; k <= 2; ++k)
      for (const int corner : { 1, 3 })
        for (int j = corner; j < corner + 2; ++j)
          for (int i = corner; i < corner + 2; ++i)
          {
            v[lattice.index(i, j, k)] = corner == 3 && i == 3 && j == 3 ? -0.5f : -1;
          }
    return shrinkwrap::DistanceGrid(lattice, std::move(v));
  }();
  const shrinkwrap::ContourEuler edgeEuler = contourEulerCharacteristic(edge, 0);
  const shrinkwrap::ContourEuler edgeSeparated =
    contourEulerCharacteristic(shrinkwrap::withFacesSeparated(edge, 0), 0);
  SW_CHECK(edgeEuler.grid == 2 && edgeEuler.halfSpacing == 4 && edgeSeparated.grid == 4 &&
      edgeSeparated.halfSpacing == 4,
    "blocks meeting along an edge: one blob, two at half the spacing; separated, two ("
      << edgeEuler.grid << ", " << edgeEuler.halfSpacing << " -> " << edgeSeparated.grid << ", "
      << edgeSeparated.halfSpacing << ")");
  // -2 and +1: the saddle is -0.5, the interpolant joins them too; the grid's own contour is kept.
  const shrinkwrap::DistanceGrid joined = ambiguousFace(-2, 1);
  SW_CHECK(contourEulerCharacteristic(joined, 0).halfSpacing == 2 &&
      contourEulerCharacteristic(joined, 0).grid == 2,
    "both join the corners below");
  SW_CHECK(
    shrinkwrap::withFacesSeparated(joined, 0).values() == joined.values(), "no corner raised");
  const shrinkwrap::TriangleSoup one =
    shrinkwrap::contourWithFewerJoins(joined, 0, shrinkwrap::convert::contour);
  const std::size_t finer = shrinkwrap::convert::contour(joined.refined(), 0).triangles.size();
  SW_CHECK(eulerOf(one) == 2 && one.triangles.size() < finer,
    "the grid's own contour: one blob, " << one.triangles.size()
                                         << " triangles (at half the spacing " << finer << ")");
  // The counts agree with the contours marching cubes builds, on a torus's field at a few levels.
  const double h = 0.1;
  shrinkwrap::GridLattice lattice;
  lattice.origin = Vec3(-1.6, -1.6, -0.6);
  lattice.spacing = Vec3(h, h, h);
  lattice.dims = { 33, 33, 13 };
  std::vector<float> values(lattice.nodeCount());
  for (std::int64_t n = 0; n < lattice.nodeCount(); ++n)
  {
    values[n] = static_cast<float>(torusDistance(lattice.position(lattice.coordinates(n))));
  }
  const shrinkwrap::DistanceGrid field(lattice, std::move(values));
  for (const double level : { 0.0, 0.1, 0.15 })
  {
    const shrinkwrap::ContourEuler euler = contourEulerCharacteristic(field, level);
    SW_CHECK(euler.grid == eulerOf(shrinkwrap::convert::contour(field, level)) &&
        euler.halfSpacing == 0 &&
        euler.halfSpacing == eulerOf(shrinkwrap::convert::contour(field.refined(), level)),
      "a torus's contour at " << level << ": the count is the contour's, 0 (" << euler.grid << ", "
                              << euler.halfSpacing << "; built "
                              << eulerOf(shrinkwrap::convert::contour(field, level)) << ", "
                              << eulerOf(shrinkwrap::convert::contour(field.refined(), level))
                              << ")");
  }
}

// A ring cut open (a tube of radius 0.2 round a circle of radius 1, cut by a slit of 1.8 cells
// whose caps lie `slit` apart), sampled on a grid of spacing h; with `speck`, a blob at its centre
// that a contour half a cell out leaves as a speck.
shrinkwrap::DistanceGrid slitRing(double h, bool speck)
{
  const double tube = 0.2, slit = 1.8 * h;
  // The caps' centres lie slit + 2 tube apart on the circle: half that angle each side of the x
  // axis.
  const double half = std::asin(0.5 * (slit + 2 * tube));
  shrinkwrap::GridLattice lattice;
  lattice.spacing = Vec3::Constant(h);
  lattice.dims = { 57, 57, 17 };
  lattice.origin = -0.5 * h * Vec3(56, 56, 16);
  std::vector<float> values(lattice.nodeCount());
  for (std::int64_t n = 0; n < lattice.nodeCount(); ++n)
  {
    const Vec3 p = lattice.position(lattice.coordinates(n));
    const double angle = std::atan2(p.y(), p.x());
    double d = std::hypot(std::hypot(p.x(), p.y()) - 1, p.z()) - tube; // to the circle
    if (std::abs(angle) < half) // the slit's side: to the nearer cap's centre
    {
      d = (p - Vec3(std::cos(half), angle < 0 ? -std::sin(half) : std::sin(half), 0)).norm() - tube;
    }
    if (speck)
    {
      d = std::min(
        d, p.norm() - 0.2 * h); // on a node: a cell out it spans 2.4 cells, half a cell out 1.4
    }
    values[n] = static_cast<float>(d);
  }
  return shrinkwrap::DistanceGrid(lattice, std::move(values));
}

// The offset start at a cell joins the ring's caps across the slit -- a handle the ring has not;
// the start takes the highest offset below it (to half a cell) with fewer handles
// (StartingSurface.cxx, fewestHandles), and the specks of the contour it takes are counted where
// they are left out.
void startsWithoutTheSlitsBridge()
{
  const double h = 0.05;
  const shrinkwrap::Contour contour = shrinkwrap::convert::contour;
  for (const bool speck : { false, true })
  {
    const shrinkwrap::DistanceGrid field = slitRing(h, speck);
    const std::string ring = speck ? "the ring with a speck: " : "the ring: ";
    SW_CHECK(shrinkwrap::handleCount(shrinkwrap::contourWithFewerJoins(field, h, contour)) == 1,
      ring << "the contour a cell out joins the caps: one handle");
    const std::vector<shrinkwrap::ContourEuler> counts =
      shrinkwrap::contourEulerCharacteristics(field, { h, 0.5 * h });
    const long long blob = speck ? 2 : 0; // a sphere's Euler characteristic
    SW_CHECK(counts.size() == 2 && counts[0].grid == 0 + blob && counts[1].grid == 2 + blob,
      ring << "Euler characteristics in one pass: " << blob << " a cell out (a handle), "
           << 2 + blob << " half a cell out");
    shrinkwrap::StartSettings settings;
    settings.offset = 1;
    settings.relaxation = 0;
    shrinkwrap::SurfaceMesh start;
    int specks = 0;
    const shrinkwrap::Status status = shrinkwrap::startingSurface(field, field.lattice().bounds(),
      nullptr, settings, shrinkwrap::FlipSettings(), contour, start, specks);
    shrinkwrap::TriangleSoup surface{ start.points(), start.triangles() };
    double nearest = INFINITY; // the start's distance from the ring, at its vertices
    for (const Vec3& p : surface.points)
    {
      nearest = std::min(nearest, field.sample(p).value);
    }
    SW_CHECK(status && shrinkwrap::handleCount(surface) == 0 && nearest > 0.4 * h,
      ring << "the start keeps the slit open: " << shrinkwrap::handleCount(surface)
           << " handles, at least " << nearest / h << " cells from the ring");
    // The lower offset taken, its speck is left out where the caller hears of it: one sphere is
    // left (V - F / 2 is 2 per sphere).
    const long long euler = static_cast<long long>(surface.points.size()) -
      static_cast<long long>(surface.triangles.size()) / 2;
    SW_CHECK(specks == (speck ? 1 : 0) && euler == 2,
      ring << specks << " speck(s) left out, Euler characteristic " << euler << " left");
  }
}

} // namespace

int TestStartingSurface(int, char*[])
{
  countsAsVTKsCaseTable();
  followsTheInterpolantsTopology();
  relaxesAContour();
  wrapsATorusFromAContour();
  wrapsATorusFromItsOffset();
  coarsensTheOffsetStart();
  startsWithoutTheSlitsBridge();
  return testing::finish("TestStartingSurface");
}
