// The target's data on its wrap and the target measured against it (issue #64): an analytic point
// field p = x^2 + 3y read at every wrap vertex within the interpolation error, a part id per
// region right wherever the vertex's closest point lies inside a cell, a point cloud's field, a
// composite's blocks (each on its own wrap, and all on one), names that clash, the switch that
// keeps the computed steps; DistanceToWrap's sign and its largest value beside the sampled one, and
// a slot narrower than the Gap Size flagged in FarFromWrap.
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkAppendPolyData.h>
#include <vtkCellData.h>
#include <vtkCellLocator.h>
#include <vtkCubeSource.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIntArray.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace
{
using testing::Vec3;
using Field = std::function<double(const Vec3&)>;

double p1(const Vec3& x)
{
  return x.x() * x.x() + 3 * x.y();
}
double p2(const Vec3& x)
{
  return 10 + x.x() - 2 * x.z();
}

// The region of a direction about the z axis: three sectors, 0, 1, 2.
int sector(const Vec3& x)
{
  const double a = std::atan2(x.y(), x.x()) + M_PI;
  return std::min(2, static_cast<int>(a / (2 * M_PI / 3)));
}

// The mean of a cell's points.
Vec3 centroidOf(vtkPolyData* mesh, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(cell, ids);
  Vec3 centroid = Vec3::Zero();
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    Vec3 x;
    mesh->GetPoint(ids->GetId(k), x.data());
    centroid += x / ids->GetNumberOfIds();
  }
  return centroid;
}

// A sphere of radius 1 about `centre`, triangles of about `edge`, with point array p (`field`) and
// cell array part (`sector` of each triangle's centroid about the centre, plus `firstPart`).
vtkSmartPointer<vtkPolyData> sphere(const Vec3& centre, const Field& field, int firstPart)
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(centre.data());
  source->SetRadius(1);
  source->SetThetaResolution(48);
  source->SetPhiResolution(48);
  source->Update();
  vtkSmartPointer<vtkPolyData> mesh = source->GetOutput();
  vtkNew<vtkDoubleArray> p;
  p->SetName("p");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    Vec3 x;
    mesh->GetPoint(i, x.data());
    p->InsertNextValue(field(x));
  }
  mesh->GetPointData()->AddArray(p);
  vtkNew<vtkIntArray> part;
  part->SetName("part");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    part->InsertNextValue(firstPart + sector(centroidOf(mesh, c) - centre));
  }
  mesh->GetCellData()->AddArray(part);
  return mesh;
}

double longestEdge(vtkPolyData* mesh)
{
  double longest = 0;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      Vec3 a, b;
      mesh->GetPoint(ids->GetId(k), a.data());
      mesh->GetPoint(ids->GetId((k + 1) % ids->GetNumberOfIds()), b.data());
      longest = std::max(longest, (a - b).norm());
    }
  }
  return longest;
}

struct Reading
{
  int vertices = 0, partsChecked = 0, partsWrong = 0;
  double largestError = 0, largestAllowed = 0, meanError = 0;
  int beyond = 0; // vertices whose p lies beyond the error allowed
};

// p on the wrap against `field` at every vertex: linear interpolation of a field whose Hessian is
// at most `hessian` on triangles of longest edge h errs by at most hessian h^2 / 2, and the vertex
// lies |Distance| off its closest point, where p changes by at most |grad p| |Distance|. The part
// against the part of the target's cell that VTK's own locator finds closest, where that point lies
// inside the cell (not on an edge shared with another part).
Reading readOn(
  vtkPolyData* wrap, vtkPolyData* target, const Field& field, double hessian, double gradient)
{
  Reading r;
  vtkDataArray* p = wrap->GetPointData()->GetArray("p");
  vtkDataArray* part = wrap->GetPointData()->GetArray("part");
  vtkDataArray* distance = wrap->GetPointData()->GetArray("Distance");
  SW_CHECK(p && part && distance, "the wrap has p, part and its own Distance");
  if (!p || !part || !distance)
  {
    return r;
  }
  const double h = longestEdge(target);
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(target);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  vtkDataArray* targetPart = target->GetCellData()->GetArray("part");
  r.vertices = static_cast<int>(wrap->GetNumberOfPoints());
  for (vtkIdType i = 0; i < wrap->GetNumberOfPoints(); ++i)
  {
    Vec3 x;
    wrap->GetPoint(i, x.data());
    const double error = std::abs(p->GetTuple1(i) - field(x));
    const double allowed =
      0.5 * hessian * h * h + gradient * std::abs(distance->GetTuple1(i)) * 1.01;
    r.largestError = std::max(r.largestError, error);
    r.largestAllowed = std::max(r.largestAllowed, allowed);
    r.meanError += error / r.vertices;
    r.beyond += error > allowed;
    double foot[3], squared, pcoords[3], weights[3];
    vtkIdType c;
    int sub;
    locator->FindClosestPoint(x.data(), foot, cell, c, sub, squared);
    double dist2;
    cell->EvaluatePosition(foot, nullptr, sub, pcoords, dist2, weights);
    if (*std::min_element(weights, weights + 3) > 1e-3)
    {
      ++r.partsChecked;
      r.partsWrong += part->GetTuple1(i) != targetPart->GetTuple1(c);
    }
  }
  return r;
}

void checkReading(const Reading& r, const std::string& name)
{
  std::cout << name << ": " << r.vertices << " vertices, |p error| mean " << r.meanError
            << " largest " << r.largestError << " (allowed up to " << r.largestAllowed << "), "
            << r.beyond << " beyond; part checked at " << r.partsChecked << ", wrong at "
            << r.partsWrong << std::endl;
  SW_CHECK(r.vertices > 500, name << ": a wrap");
  SW_CHECK(r.beyond == 0, name << ": p within the interpolation error at every vertex");
  SW_CHECK(r.partsChecked > r.vertices / 2, name << ": most vertices stand inside a cell");
  SW_CHECK(r.partsWrong == 0, name << ": the part of the closest cell at every vertex");
}

// The wrap (and with it the target as measured).
vtkPolyData* wrapOf(vtkShrinkWrapFilter* w)
{
  w->Update();
  return vtkPolyData::SafeDownCast(w->GetOutputDataObject(0));
}

void oneMesh()
{
  vtkSmartPointer<vtkPolyData> target = sphere(Vec3::Zero(), p1, 0);
  {
    // The target as measured comes with the wrap, whichever port is asked for; asked again, from
    // the cached steps.
    vtkNew<vtkShrinkWrapFilter> once;
    once->SetInputData(target);
    once->Update(0);
    auto* measured = vtkPolyData::SafeDownCast(once->GetOutputDataObject(1));
    const int computed = once->GetNumberOfComputedSteps();
    once->Update(1);
    SW_CHECK(measured && measured->GetNumberOfPoints() == target->GetNumberOfPoints() &&
        measured->GetPointData()->GetArray("DistanceToWrap") &&
        once->GetNumberOfComputedSteps() == computed,
      "port 1 measured with the wrap");
  }
  vtkNew<vtkShrinkWrapFilter> w;
  w->SetInputData(target);
  vtkPolyData* wrap = wrapOf(w);
  // p = x^2 + 3y: Hessian norm 2, |grad p| <= sqrt(4 + 9) on the unit sphere (and just off it).
  checkReading(readOn(wrap, target, p1, 2, std::sqrt(13.0) * 1.05), "sphere");
  SW_CHECK(wrap->GetPointData()->GetArray("Normals (target)"),
    "the target's Normals passed as Normals (target)");
  SW_CHECK(wrap->GetPointData()->GetNormals() &&
      std::string(wrap->GetPointData()->GetNormals()->GetName()) == "Normals",
    "the wrap's own normals stay its Normals");

  // The target as measured: DistanceToWrap signed, and its largest beside the sampled one.
  auto* measured = vtkPolyData::SafeDownCast(w->GetOutputDataObject(1));
  vtkDataArray* d = measured ? measured->GetPointData()->GetArray("DistanceToWrap") : nullptr;
  vtkDataArray* sampled = wrap->GetFieldData()->GetArray("SampledDistances");
  SW_CHECK(d && d->GetNumberOfTuples() == target->GetNumberOfPoints() && sampled &&
      sampled->GetNumberOfComponents() == 4,
    "the target measured at each of its points; the summary's sampled distances");
  if (d && sampled)
  {
    double largest = 0;
    for (vtkIdType i = 0; i < d->GetNumberOfTuples(); ++i)
    {
      largest = std::max(largest, std::abs(d->GetTuple1(i)));
    }
    const double targetToWrap = sampled->GetComponent(0, 3);
    std::cout << "largest |DistanceToWrap| " << largest << ", sampled target to wrap largest "
              << targetToWrap << std::endl;
    SW_CHECK(std::abs(largest - targetToWrap) <= 0.05 * targetToWrap,
      "largest |DistanceToWrap| within 5% of the sampled largest distance target to wrap");
    // Independently: a target point's sign against the wrap as a closed surface (inside where its
    // distance from the centre is below the wrap's there: the wrap is star-shaped about it).
    int wrongSide = 0;
    vtkNew<vtkCellLocator> onWrap;
    onWrap->SetDataSet(wrap);
    onWrap->BuildLocator();
    for (vtkIdType i = 0; i < measured->GetNumberOfPoints(); ++i)
    {
      Vec3 x, foot;
      measured->GetPoint(i, x.data());
      vtkIdType c;
      int sub;
      double squared;
      onWrap->FindClosestPoint(x.data(), foot.data(), c, sub, squared);
      const double outside = x.norm() - foot.norm();
      wrongSide += std::abs(outside) > 1e-9 && (outside > 0) != (d->GetTuple1(i) > 0);
      wrongSide += std::abs(std::abs(d->GetTuple1(i)) - std::sqrt(squared)) > 1e-9;
    }
    SW_CHECK(wrongSide == 0, "DistanceToWrap is the distance to the wrap, > 0 outside it");
  }

  // Pass Target Arrays off: the wrap's own arrays alone, from the same computed steps.
  const int computed = w->GetNumberOfComputedSteps();
  w->SetPassTargetArrays(false);
  wrap = wrapOf(w);
  SW_CHECK(!wrap->GetPointData()->GetArray("p") && wrap->GetPointData()->GetArray("Distance"),
    "Pass Target Arrays off: no p on the wrap");
  SW_CHECK(w->GetNumberOfComputedSteps() == computed, "switching it keeps the computed steps");
  w->SetPassTargetArrays(true);
  wrap = wrapOf(w);
  SW_CHECK(wrap->GetPointData()->GetArray("p"), "and back on, p again");

  // The target's arrays are read anew when only they change (the same geometry, the same run).
  vtkNew<vtkPolyData> changed;
  changed->DeepCopy(target);
  vtkDataArray* p = changed->GetPointData()->GetArray("p");
  for (vtkIdType i = 0; i < p->GetNumberOfTuples(); ++i)
  {
    p->SetTuple1(i, 5.0);
  }
  w->SetInputData(changed);
  wrap = wrapOf(w);
  vtkDataArray* read = wrap->GetPointData()->GetArray("p");
  double range[2] = { 0, 0 };
  if (read)
  {
    read->GetRange(range);
  }
  SW_CHECK(read && std::abs(range[0] - 5) < 1e-12 && std::abs(range[1] - 5) < 1e-12,
    "new values of the target's arrays show on the wrap");
}

// Points on the unit sphere with p; the wrap reads p weighted as the fit placed it.
void cloud()
{
  const std::vector<Vec3> points = testing::spherePoints(20000, 0, 5);
  vtkNew<vtkPolyData> target;
  vtkNew<vtkPoints> xyz;
  vtkNew<vtkDoubleArray> p;
  p->SetName("p");
  vtkNew<vtkCellArray> vertices;
  for (const Vec3& x : points)
  {
    vertices->InsertNextCell(1);
    vertices->InsertCellPoint(xyz->InsertNextPoint(x.data()));
    p->InsertNextValue(p1(x));
  }
  target->SetPoints(xyz);
  target->SetVerts(vertices);
  target->GetPointData()->AddArray(p);
  vtkNew<vtkShrinkWrapFilter> w;
  w->SetInputData(target);
  vtkPolyData* wrap = wrapOf(w);
  vtkDataArray* read = wrap->GetPointData()->GetArray("p");
  vtkDataArray* distance = wrap->GetPointData()->GetArray("Distance");
  SW_CHECK(read && distance && wrap->GetNumberOfPoints() > 500, "a cloud's p on its wrap");
  if (!read || !distance)
  {
    return;
  }
  // The fit averages p over its neighbourhood (a few spacings wide): on the unit sphere p's
  // average over a cap of radius r about x differs from p(x) by at most |grad p| times the cap's
  // centroid offset (about r^2 / 2) plus the Hessian's r^2 / 2 share, and the vertex lies
  // |Distance| off the surface; r: five spacings.
  const double spacing = std::sqrt(4 * M_PI / points.size());
  const double r = 5 * spacing;
  double largest = 0, mean = 0, largestNearest = 0;
  int beyond = 0;
  for (vtkIdType i = 0; i < wrap->GetNumberOfPoints(); ++i)
  {
    Vec3 x;
    wrap->GetPoint(i, x.data());
    const double error = std::abs(read->GetTuple1(i) - p1(x));
    const double allowed =
      std::sqrt(13.0) * (0.5 * r * r + std::abs(distance->GetTuple1(i))) + r * r;
    beyond += error > allowed;
    largest = std::max(largest, error);
    mean += error / wrap->GetNumberOfPoints();
    largestNearest = std::max(largestNearest, allowed);
  }
  std::cout << "cloud: |p error| mean " << mean << " largest " << largest << " (allowed up to "
            << largestNearest << "), " << beyond << " beyond" << std::endl;
  SW_CHECK(beyond == 0, "a cloud's p within the fit's error at every vertex");
}

// Two spheres, p and the parts differing between them: a composite wrapped block by block reads
// each block's data on its own wrap; wrapped as one, each vertex reads the block it stands on.
void blocks()
{
  vtkSmartPointer<vtkPolyData> a = sphere(Vec3::Zero(), p1, 0);
  vtkSmartPointer<vtkPolyData> b = sphere(Vec3(3, 0, 0), p2, 10);
  vtkNew<vtkMultiBlockDataSet> target;
  target->SetNumberOfBlocks(2);
  target->SetBlock(0, a);
  target->SetBlock(1, b);
  vtkNew<vtkShrinkWrapFilter> w;
  w->SetInputData(target);
  wrapOf(w);
  auto* wraps = vtkMultiBlockDataSet::SafeDownCast(w->GetOutputDataObject(0));
  auto* measured = vtkMultiBlockDataSet::SafeDownCast(w->GetOutputDataObject(1));
  SW_CHECK(
    wraps && wraps->GetNumberOfBlocks() == 2 && measured && measured->GetNumberOfBlocks() == 2,
    "a wrap and a measured target per block");
  if (!wraps || !measured)
  {
    return;
  }
  checkReading(
    readOn(vtkPolyData::SafeDownCast(wraps->GetBlock(0)), a, p1, 2, std::sqrt(13.0) * 1.05),
    "block 0");
  checkReading(
    readOn(vtkPolyData::SafeDownCast(wraps->GetBlock(1)), b, p2, 0, std::sqrt(5.0)), "block 1");
  for (int k = 0; k < 2; ++k)
  {
    auto* leaf = vtkPolyData::SafeDownCast(measured->GetBlock(k));
    SW_CHECK(leaf && leaf->GetPointData()->GetArray("DistanceToWrap") &&
        leaf->GetNumberOfPoints() == (k ? b : a)->GetNumberOfPoints(),
      "block " << k << " measured against its wrap");
  }

  // As one target (Wrap Per Block off): each vertex reads the sphere it stands on; the measured
  // target keeps the blocks.
  w->SetWrapPerBlock(false);
  vtkPolyData* one = wrapOf(w);
  vtkDataArray* p = one->GetPointData()->GetArray("p");
  vtkDataArray* part = one->GetPointData()->GetArray("part");
  int wrong = 0;
  for (vtkIdType i = 0; p && part && i < one->GetNumberOfPoints(); ++i)
  {
    Vec3 x;
    one->GetPoint(i, x.data());
    const bool second = x.x() > 1.5;
    wrong += std::abs(p->GetTuple1(i) - (second ? p2(x) : p1(x))) > 0.05;
    wrong += (part->GetTuple1(i) >= 10) != second;
  }
  SW_CHECK(p && part && one->GetNumberOfPoints() > 1000 && wrong == 0,
    "wrapped as one, each vertex reads its own block (" << wrong << " wrong)");
  SW_CHECK(vtkMultiBlockDataSet::SafeDownCast(w->GetOutputDataObject(1)),
    "the target measured keeps its blocks");
}

// Two boxes 0.1 apart, a slot that a Gap Size of 0.4 bridges: the slot's faces lie far from the
// wrap (flagged in FarFromWrap), the outer faces on it.
vtkSmartPointer<vtkPolyData> slottedBoxes(int subdivisions)
{
  vtkNew<vtkAppendPolyData> boxes;
  for (double side : { -1.0, 1.0 })
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetBounds(side < 0 ? -1.0 : 0.05, side < 0 ? -0.05 : 1.0, -1, 1, -1, 1);
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(cube->GetOutputPort());
    vtkNew<vtkLinearSubdivisionFilter> finer;
    finer->SetInputConnection(triangles->GetOutputPort());
    finer->SetNumberOfSubdivisions(subdivisions);
    boxes->AddInputConnection(finer->GetOutputPort());
  }
  boxes->Update();
  return boxes->GetOutput();
}

// LargestDistanceToWrap: the largest over the whole surface, at least the largest at its points,
// within 2% of a dense sample's (a million points by area).
double checkLargest(vtkShrinkWrapFilter* w, vtkPolyData* target, const std::string& name)
{
  auto* measured = vtkPolyData::SafeDownCast(w->GetOutputDataObject(1));
  vtkDataArray* largest = measured->GetFieldData()->GetArray("LargestDistanceToWrap");
  vtkDataArray* d = measured->GetPointData()->GetArray("DistanceToWrap");
  const shrinkwrap::TriangleSoup soup = testing::triangulated(target);
  const shrinkwrap::TriangleSoup wrap =
    testing::triangulated(vtkPolyData::SafeDownCast(w->GetOutputDataObject(0)));
  const double diagonal = soup.bounds().diagonal();
  const double sampled =
    testing::oneSided(shrinkwrap::samplePoints(soup, 1000000, 3), wrap, diagonal).largest *
    diagonal / 100;
  double atPoints = 0;
  for (vtkIdType i = 0; d && i < d->GetNumberOfTuples(); ++i)
  {
    atPoints = std::max(atPoints, std::abs(d->GetTuple1(i)));
  }
  const double field = largest ? largest->GetTuple1(0) : 0.0;
  std::cout << name << ": largest distance to the wrap at the points " << atPoints
            << ", over the surface " << field << ", sampled densely " << sampled << std::endl;
  SW_CHECK(largest && field >= atPoints && field >= sampled / 1.02 && field <= 1.02 * sampled,
    name << ": LargestDistanceToWrap, the largest over the surface");
  return field / std::max(atPoints, 1e-300);
}

void slot()
{
  vtkSmartPointer<vtkPolyData> boxes = slottedBoxes(3);
  vtkNew<vtkShrinkWrapFilter> w;
  w->SetInputData(boxes);
  w->SetGapSize(0.4);
  wrapOf(w);
  auto* measured = vtkPolyData::SafeDownCast(w->GetOutputDataObject(1));
  vtkDataArray* far = measured ? measured->GetCellData()->GetArray("FarFromWrap") : nullptr;
  SW_CHECK(far && far->GetNumberOfTuples() == measured->GetNumberOfCells(), "FarFromWrap per cell");
  if (!far)
  {
    return;
  }
  double slotArea = 0, slotFlagged = 0, outerFlagged = 0;
  int deepCells = 0, deepFlagged = 0;
  for (vtkIdType c = 0; c < measured->GetNumberOfCells(); ++c)
  {
    const Vec3 centroid = centroidOf(measured, c);
    const bool inSlot = std::abs(centroid.x()) < 0.06;
    (inSlot ? slotArea : outerFlagged) += inSlot ? 1 : far->GetTuple1(c);
    slotFlagged += inSlot && far->GetTuple1(c) > 0.5;
    // Deeper in the slot than 0.5 from its mouth: farther than the Gap Size from the bridge.
    const bool deep = inSlot && std::max(std::abs(centroid.y()), std::abs(centroid.z())) < 0.5;
    deepCells += deep;
    deepFlagged += deep && far->GetTuple1(c) == 1;
  }
  std::cout << "slot: " << slotFlagged << " of its " << slotArea << " cells flagged, "
            << deepFlagged << " of the " << deepCells
            << " deep ones wholly; outer cells' FarFromWrap summed " << outerFlagged << std::endl;
  SW_CHECK(deepCells > 0 && deepFlagged == deepCells, "the slot's depth flagged far from the wrap");
  SW_CHECK(slotFlagged > 0.15 * slotArea, "the slot flagged beyond its depth too");
  SW_CHECK(outerFlagged == 0, "no outer face flagged");
  checkLargest(w, boxes, "slot");

  // Two triangles a face: the slot's deepest point lies inside a triangle, not at a point.
  vtkSmartPointer<vtkPolyData> coarse = slottedBoxes(0);
  w->SetInputData(coarse);
  wrapOf(w);
  SW_CHECK(checkLargest(w, coarse, "coarse slot") > 1.2,
    "the largest inside a triangle, beyond the largest at the points");
}

// The target's own "Distance" point array: passed as "Distance (target)", the wrap's kept.
void clash()
{
  vtkSmartPointer<vtkPolyData> target = sphere(Vec3::Zero(), p1, 0);
  vtkNew<vtkDoubleArray> distance;
  distance->DeepCopy(target->GetPointData()->GetArray("p"));
  distance->SetName("Distance");
  target->GetPointData()->AddArray(distance);
  vtkNew<vtkShrinkWrapFilter> w;
  w->SetInputData(target);
  vtkPolyData* wrap = wrapOf(w);
  vtkDataArray* own = wrap->GetPointData()->GetArray("Distance");
  vtkDataArray* passed = wrap->GetPointData()->GetArray("Distance (target)");
  double range[2] = { 0, 0 };
  if (own)
  {
    own->GetRange(range);
  }
  SW_CHECK(passed && own && std::max(std::abs(range[0]), std::abs(range[1])) < 0.05,
    "a clashing name is passed renamed, the wrap's own Distance kept");
}
} // namespace

int TestTargetData(int, char*[])
{
  oneMesh();
  cloud();
  blocks();
  slot();
  clash();
  return testing::finish("TestTargetData");
}
