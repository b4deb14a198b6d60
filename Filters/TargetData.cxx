#include "TargetData.h"

#include "RankInputs.h"
#include "VTKConversions.h"

#include "Wrap/TargetFeet.h"
#include "Wrap/TargetMeasure.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace shrinkwrap
{
namespace convert
{

vtkSmartPointer<vtkDataObject> wholeTarget(vtkDataObject* target)
{
  if (vtkCompositeDataSet::SafeDownCast(target))
  {
    return appendedLeaves(target);
  }
  return target;
}

std::unique_ptr<TargetCarrier> makeCarrier(vtkDataObject* whole,
  std::shared_ptr<const TriangleSoup> triangles, std::shared_ptr<const DistanceSource> source)
{
  auto carrier = std::make_unique<TargetCarrier>();
  SoupCounts counts;
  const TriangleSoup again = soupOf(polygonMeshes(whole).meshes, counts, &carrier->cells);
  if (!triangles || again.triangles != triangles->triangles)
  {
    return nullptr;
  }
  carrier->triangles = std::move(triangles);
  carrier->source = std::dynamic_pointer_cast<const TriangleSource>(source);
  if (!carrier->source)
  {
    carrier->tree = std::make_unique<AABBTree>(*carrier->triangles);
  }
  return carrier;
}

NearestOnSoup TargetCarrier::nearest() const
{
  if (this->source)
  {
    return [source = this->source.get()](const Vec3& p) {
      const SourcePoint s = source->closestPoint(p, std::numeric_limits<double>::infinity());
      return std::make_pair(source->inputTriangle(s.element), s.point);
    };
  }
  return [tree = this->tree.get()](const Vec3& p) {
    const ClosestHit hit = tree->closestPoint(p);
    return std::make_pair(hit.triangle, hit.point);
  };
}

bool hasArraysToPass(vtkDataObject* target)
{
  auto counts = [](vtkFieldData* data) {
    int n = data ? data->GetNumberOfArrays() : 0;
    n -= data && data->HasArray(vtkDataSetAttributes::GhostArrayName()) ? 1 : 0;
    return n;
  };
  int arrays = target ? counts(target->GetFieldData()) : 0;
  for (vtkDataSet* leaf : vtkCompositeDataSet::GetDataSets(target))
  {
    arrays += counts(leaf->GetPointData()) + counts(leaf->GetCellData());
  }
  return arrays > 0;
}

namespace
{
// The name of a passed array on the wrap: its own, or with `suffix` where the wrap has that name.
std::string freeName(
  const char* name, vtkFieldData* taken, const char* suffix, std::vector<std::string>& renamed)
{
  std::string given = name ? name : "";
  if (given.empty() || taken->HasArray(given.c_str()))
  {
    renamed.push_back(given);
    given += suffix;
  }
  return given;
}

// The arrays of `from` onto `to` under free names; the ghost mark is the target's, not the wrap's.
void moveArrays(vtkFieldData* from, vtkFieldData* to, vtkFieldData* taken, const char* suffix,
  std::vector<std::string>& renamed)
{
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = from->GetAbstractArray(a);
    const char* name = array->GetName();
    if (name && std::string(name) == vtkDataSetAttributes::GhostArrayName())
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> moved = array;
    const std::string free = freeName(name, taken, suffix, renamed);
    if (free != (name ? name : ""))
    {
      moved = vtkSmartPointer<vtkAbstractArray>::Take(array->NewInstance());
      moved->DeepCopy(array);
      moved->SetName(free.c_str());
    }
    to->AddArray(moved);
  }
}

// The target's point arrays at the feet on its triangles, and its cell arrays from their cells.
void readOnTriangles(vtkDataObject* whole, const TargetCarrier& carrier, const TargetFeet& feet,
  vtkPointData* points, vtkPointData* cells)
{
  const PolygonMeshes input = polygonMeshes(whole);
  const int meshes = static_cast<int>(input.meshes.size());
  std::vector<vtkIdType> firstPoint(meshes + 1, 0), firstCell(meshes + 1, 0);
  vtkDataSetAttributes::FieldList pointList(meshes), cellList(meshes);
  for (int m = 0; m < meshes; ++m)
  {
    vtkPolyData* mesh = input.meshes[m];
    firstPoint[m + 1] = firstPoint[m] + mesh->GetNumberOfPoints();
    firstCell[m + 1] = firstCell[m] + mesh->GetNumberOfCells();
    m == 0 ? pointList.InitializeFieldList(mesh->GetPointData())
           : pointList.IntersectFieldList(mesh->GetPointData());
    m == 0 ? cellList.InitializeFieldList(mesh->GetCellData())
           : cellList.IntersectFieldList(mesh->GetCellData());
  }
  const auto n = static_cast<vtkIdType>(feet.size());
  points->InterpolateAllocate(pointList, n);
  cells->CopyAllocate(cellList, n);
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(3);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const int t = std::max(feet.element[i], 0); // every vertex has a foot on a non-empty soup
    const vtkIdType cell = carrier.cells[t];
    const int m = static_cast<int>(std::upper_bound(firstCell.begin(), firstCell.end(), cell) -
                    firstCell.begin()) -
      1;
    double weights[3];
    for (int k = 0; k < 3; ++k)
    {
      ids->SetId(k, feet.points[3 * i + k] - firstPoint[m]);
      weights[k] = feet.weights[3 * i + k];
    }
    vtkPolyData* mesh = input.meshes[m];
    points->InterpolatePoint(pointList, mesh->GetPointData(), m, i, ids, weights);
    cells->CopyData(cellList, mesh->GetCellData(), m, cell - firstCell[m], i);
  }
}

// The target's point arrays at the feet on its cloud's fitted surface.
void readOnPoints(vtkDataObject* whole, const TargetFeet& feet, vtkPointData* points)
{
  auto* data = vtkDataSet::SafeDownCast(whole);
  if (!data)
  {
    return;
  }
  const auto n = static_cast<vtkIdType>(feet.size());
  points->InterpolateAllocate(data->GetPointData(), n);
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const std::int64_t b = feet.begin[i], e = feet.begin[i + 1];
    ids->SetNumberOfIds(e - b);
    for (std::int64_t k = b; k < e; ++k)
    {
      ids->SetId(k - b, feet.points[k]);
    }
    points->InterpolatePoint(
      data->GetPointData(), i, ids, const_cast<double*>(feet.weights.data() + b));
  }
}
} // namespace

void passTargetArrays(vtkDataObject* whole, const TargetCarrier* carrier, const PointCloud* cloud,
  vtkPolyData* wrap, std::vector<std::string>& renamed)
{
  const std::vector<Vec3> x = pointsOf<std::vector<Vec3>>(wrap);
  vtkNew<vtkPointData> points, cells;
  if (carrier)
  {
    readOnTriangles(
      whole, *carrier, feetOnTriangles(x, *carrier->triangles, carrier->nearest()), points, cells);
  }
  else if (cloud && cloud->surface)
  {
    readOnPoints(whole, feetOnPoints(x, *cloud->surface), points);
  }
  vtkPointData* onWrap = wrap->GetPointData();
  moveArrays(points, onWrap, onWrap, " (target)", renamed);
  moveArrays(cells, onWrap, onWrap, " (target cells)", renamed);
  if (whole && whole->GetFieldData())
  {
    moveArrays(
      whole->GetFieldData(), wrap->GetFieldData(), wrap->GetFieldData(), " (target)", renamed);
  }
}

namespace
{
// The target as a surface with its data: a mesh itself (shallow), other data its outer surface,
// data without cells its points.
vtkSmartPointer<vtkPolyData> surfaceWithData(vtkDataSet* target)
{
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  if (auto* mesh = vtkPolyData::SafeDownCast(target))
  {
    surface->ShallowCopy(mesh);
  }
  else if (target->GetNumberOfCells() > 0)
  {
    vtkNew<vtkDataSetSurfaceFilter> outer;
    outer->SetInputData(target);
    outer->Update();
    surface->ShallowCopy(outer->GetOutput());
  }
  else
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(target->GetNumberOfPoints());
    for (vtkIdType i = 0; i < target->GetNumberOfPoints(); ++i)
    {
      points->SetPoint(i, target->GetPoint(i));
    }
    surface->SetPoints(points);
    surface->GetPointData()->ShallowCopy(target->GetPointData());
  }
  return surface;
}

// Per cell: the share of its area farther than `gap` (from its triangles' shares); for cells
// without area (vertices, lines), the share of its existing points.
vtkSmartPointer<vtkDoubleArray> farFromWrap(vtkPolyData* surface, const TriangleSoup& soup,
  const std::vector<vtkIdType>& cellOf, const std::vector<double>& distance,
  const DistanceSource& wrap, double gap)
{
  const vtkIdType cells = surface->GetNumberOfCells();
  std::vector<double> far(cells, 0.0), area(cells, 0.0);
  const std::vector<double> share = farShares(soup, wrap, gap, &distance);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& c = soup.triangles[t];
    const double a = 0.5 *
      (soup.points[c[1]] - soup.points[c[0]]).cross(soup.points[c[2]] - soup.points[c[0]]).norm();
    far[cellOf[t]] += a * share[t];
    area[cellOf[t]] += a;
  }
  auto result = vtkSmartPointer<vtkDoubleArray>::New();
  result->SetName("FarFromWrap");
  result->SetNumberOfTuples(cells);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells; ++c)
  {
    if (area[c] > 0)
    {
      result->SetValue(c, far[c] / area[c]);
      continue;
    }
    surface->GetCellPoints(c, ids);
    int beyond = 0, named = 0; // a cell may name points that do not exist: those are left out
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType id = ids->GetId(k);
      if (id >= 0 && id < static_cast<vtkIdType>(distance.size()))
      {
        beyond += std::abs(distance[id]) > gap;
        ++named;
      }
    }
    result->SetValue(c, named > 0 ? double(beyond) / named : 0.0);
  }
  return result;
}
} // namespace

vtkSmartPointer<vtkPolyData> measureTarget(
  vtkDataSet* target, const DistanceSource& wrap, double gap, bool largest)
{
  vtkSmartPointer<vtkPolyData> surface = surfaceWithData(target);
  const std::vector<Vec3> x = pointsOf<std::vector<Vec3>>(surface);
  const std::vector<double> d = signedDistances(x.data(), x.size(), wrap);
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("DistanceToWrap");
  distance->SetNumberOfTuples(static_cast<vtkIdType>(d.size()));
  std::copy(d.begin(), d.end(), distance->GetPointer(0));
  surface->GetPointData()->AddArray(distance);
  surface->GetPointData()->SetActiveScalars("DistanceToWrap");
  SoupCounts counts;
  std::vector<vtkIdType> cellOf;
  const TriangleSoup soup = soupOf({ surface.Get() }, counts, &cellOf);
  surface->GetCellData()->AddArray(farFromWrap(surface, soup, cellOf, d, wrap, gap));
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(surface->GetFieldData());
  auto add = [&](const char* name, double value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    fields->AddArray(a);
  };
  add("GapSize", gap);
  if (largest)
  {
    double atPoints = 0;
    for (double v : d)
    {
      atPoints = std::max(atPoints, std::abs(v));
    }
    add(
      "LargestDistanceToWrap", soup.triangles.empty() ? atPoints : largestDistance(soup, wrap, d));
  }
  surface->SetFieldData(fields);
  return surface;
}

} // namespace convert
} // namespace shrinkwrap
