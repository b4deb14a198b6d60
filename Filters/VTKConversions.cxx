#include "VTKConversions.h"

#include "Distance/ContourTopology.h"

#include "Surface/MeshQuality.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shrinkwrap
{
namespace convert
{

namespace
{
// Calls visit(n, ids) for every cell of a cell array.
template <typename Visit>
void forEachCell(vtkCellArray* cells, Visit&& visit)
{
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    visit(n, ids);
  }
}

// Triangles of a polygon: ear-cut by vtkPolygon, or a fan where ear cutting fails (degenerate
// polygons, which still have their distances).
template <typename Add>
void triangulatePolygon(vtkIdType n, const vtkIdType* ids, vtkPoints* points, vtkPolygon* polygon,
  vtkIdList* corners, Add&& addTriangle)
{
  polygon->Initialize(n, ids, points);
  if (polygon->Triangulate(corners) && corners->GetNumberOfIds() > 0)
  {
    for (vtkIdType k = 0; k + 2 < corners->GetNumberOfIds(); k += 3)
    {
      addTriangle(ids[corners->GetId(k)], ids[corners->GetId(k + 1)], ids[corners->GetId(k + 2)]);
    }
    return;
  }
  for (vtkIdType k = 1; k + 1 < n; ++k)
  {
    addTriangle(ids[0], ids[k], ids[k + 1]);
  }
}

// Appends a mesh to the paper's triangle soup: polygons of any size and strips. Cells naming points
// that do not exist are counted in badCells and left out.
void appendToSoup(vtkPolyData* input, TriangleSoup& soup, long long& badCells,
  std::vector<vtkIdType>* cells = nullptr)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  const vtkIdType first = static_cast<vtkIdType>(soup.points.size());
  soup.points.resize(first + np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    points->GetPoint(i, soup.points[first + i].data());
  }
  // The cell each triangle comes of, in the mesh's numbering (vertices, lines, polygons, strips).
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines() - 1;
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    soup.triangles.push_back(
      { static_cast<int>(first + a), static_cast<int>(first + b), static_cast<int>(first + c) });
    if (cells)
    {
      cells->push_back(cell);
    }
  };
  auto valid = [&](vtkIdType n, const vtkIdType* ids) {
    const bool ok = std::all_of(ids, ids + n, [np](vtkIdType id) { return id >= 0 && id < np; });
    badCells += !ok;
    return ok;
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> corners;
  forEachCell(input->GetPolys(), [&](vtkIdType n, const vtkIdType* ids) {
    ++cell;
    if (!valid(n, ids) || n < 3)
    {
      return;
    }
    if (n == 3)
    {
      addTriangle(ids[0], ids[1], ids[2]);
      return;
    }
    triangulatePolygon(n, ids, points, polygon, corners, addTriangle);
  });
  forEachCell(input->GetStrips(), [&](vtkIdType n, const vtkIdType* ids) {
    ++cell;
    const bool ok = valid(n, ids);
    for (vtkIdType k = 0; ok && k + 2 < n; ++k) // strips alternate orientation
    {
      k % 2 == 0 ? addTriangle(ids[k], ids[k + 1], ids[k + 2])
                 : addTriangle(ids[k + 1], ids[k], ids[k + 2]);
    }
  });
}

void extendBySurface(vtkPolyData* input, Box& box)
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType np = points ? points->GetNumberOfPoints() : 0;
  for (vtkCellArray* cells : { input->GetPolys(), input->GetStrips() })
  {
    forEachCell(cells, [&](vtkIdType n, const vtkIdType* ids) {
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] >= 0 && ids[k] < np)
        {
          Vec3 p;
          points->GetPoint(ids[k], p.data());
          box.extend(p);
        }
      }
    });
  }
}
} // namespace

PolygonMeshes polygonMeshes(vtkDataObject* input)
{
  PolygonMeshes found;
  for (vtkDataSet* leaf : vtkCompositeDataSet::GetDataSets(input))
  {
    if (auto* mesh = vtkPolyData::SafeDownCast(leaf))
    {
      found.meshes.push_back(mesh);
    }
    else if (leaf->GetNumberOfCells() > 0)
    {
      vtkNew<vtkDataSetSurfaceFilter> surface;
      surface->SetInputData(leaf);
      surface->Update();
      found.extracted.emplace_back(surface->GetOutput());
      found.meshes.push_back(found.extracted.back());
      const std::string kind = leaf->GetClassName();
      if (found.extractedFrom.find(kind) == std::string::npos)
      {
        found.extractedFrom += (found.extractedFrom.empty() ? "" : ", ") + kind;
      }
    }
  }
  return found;
}

namespace
{
template <typename F>
void forEachPoint(vtkDataObject* input, F&& f)
{
  for (vtkDataSet* leaf : vtkCompositeDataSet::GetDataSets(input))
  {
    const vtkIdType n = leaf->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i)
    {
      Vec3 p;
      leaf->GetPoint(i, p.data());
      f(p);
    }
  }
}
} // namespace

template <typename Points>
Points pointsOf(vtkDataObject* input)
{
  Points points;
  points.reserve(input ? input->GetNumberOfElements(vtkDataObject::POINT) : 0);
  forEachPoint(input, [&](const Vec3& p) { points.push_back(p); });
  return points;
}

Box pointBounds(vtkDataObject* input)
{
  Box box;
  forEachPoint(input, [&](const Vec3& p) { box.extend(p); });
  return box;
}

template std::vector<Vec3> pointsOf<std::vector<Vec3>>(vtkDataObject*);
template PointList pointsOf<PointList>(vtkDataObject*);

template <typename Points>
Points loosePointsOf(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<char> used(n, 0);
  const auto mark = [&](vtkIdType count, const vtkIdType* ids) {
    for (vtkIdType i = 0; i < count; ++i)
    {
      if (ids[i] >= 0 && ids[i] < n)
      {
        used[ids[i]] = 1;
      }
    }
  };
  forEachCell(mesh->GetPolys(), mark);
  forEachCell(mesh->GetStrips(), mark);
  Points points;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!used[i])
    {
      double p[3];
      mesh->GetPoint(i, p);
      points.emplace_back(p[0], p[1], p[2]);
    }
  }
  return points;
}

template std::vector<Vec3> loosePointsOf<std::vector<Vec3>>(vtkPolyData*);
template PointList loosePointsOf<PointList>(vtkPolyData*);

Geometry chooseGeometry(int inputGeometry, bool hasPolygons)
{
  switch (inputGeometry)
  {
    case 1:
      return { true, false };
    case 2:
      return { false, true };
    case 3:
      return { true, true };
    default:
      return { hasPolygons, !hasPolygons };
  }
}

const char* geometryName(int inputGeometry)
{
  static const char* const names[] = { "Automatic", "Polygons", "Points", "PolygonsAndPoints" };
  return names[std::clamp(inputGeometry, 0, 3)];
}

TriangleSoup soupOf(
  const std::vector<vtkPolyData*>& meshes, SoupCounts& counts, std::vector<vtkIdType>* cells)
{
  TriangleSoup soup;
  vtkIdType firstCell = 0;
  for (vtkPolyData* mesh : meshes)
  {
    counts.lines += mesh->GetNumberOfLines();
    counts.vertices += mesh->GetNumberOfVerts();
    const std::size_t from = cells ? cells->size() : 0;
    appendToSoup(mesh, soup, counts.badCells, cells);
    for (std::size_t t = from; cells && t < cells->size(); ++t)
    {
      (*cells)[t] += firstCell;
    }
    firstCell += mesh->GetNumberOfCells();
  }
  return soup;
}

Status surfaceOf(vtkPolyData* mesh, TriangleSoup& surface)
{
  const Status refused =
    Status::failure("it must be made of triangles only, with finite points and valid point ids");
  bool triangles = true;
  forEachCell(
    mesh->GetPolys(), [&](vtkIdType n, const vtkIdType*) { triangles = triangles && n == 3; });
  if (!triangles)
  {
    return refused;
  }
  long long badCells = 0;
  surface = TriangleSoup();
  appendToSoup(mesh, surface, badCells);
  if (badCells > 0 || surface.triangles.empty() || mesh->GetNumberOfStrips() > 0 ||
    !surface.allFinite())
  {
    return refused;
  }
  return {};
}

Box surfaceBounds(const std::vector<vtkPolyData*>& meshes)
{
  Box box;
  for (vtkPolyData* mesh : meshes)
  {
    extendBySurface(mesh, box);
  }
  return box;
}

Box boundsOf(vtkDataSet* data)
{
  Box box;
  double b[6];
  data->GetBounds(b);
  if (data->GetNumberOfPoints() > 0)
  {
    box.extend(Vec3(b[0], b[2], b[4]));
    box.extend(Vec3(b[1], b[3], b[5]));
  }
  return box;
}

GridLattice latticeOf(vtkImageData* image)
{
  GridLattice lattice;
  int extent[6];
  image->GetExtent(extent);
  image->GetSpacing(lattice.spacing.data());
  image->GetOrigin(lattice.origin.data());
  for (int a = 0; a < 3; ++a)
  {
    lattice.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    lattice.origin[a] += extent[2 * a] * lattice.spacing[a];
  }
  return lattice;
}

Status gridOf(vtkImageData* image, const char* name, DistanceGrid& grid)
{
  vtkDataArray* values = image ? image->GetPointData()->GetArray(name) : nullptr;
  if (!values || values->GetNumberOfComponents() != 1)
  {
    return Status::failure(std::string("the distance field has no point array \"") + name + "\"");
  }
  const GridLattice lattice = latticeOf(image);
  const double* direction = image->GetDirectionMatrix()->GetData();
  for (int k = 0; k < 9; ++k)
  {
    if (direction[k] != (k % 4 == 0 ? 1.0 : 0.0))
    {
      return Status::failure(
        "the distance field's image is rotated (its direction matrix is not the identity); "
        "resample it to an axis-aligned image first (Resample To Image)");
    }
  }
  if (lattice.dims[0] < 2 || lattice.dims[1] < 2 || lattice.dims[2] < 2 ||
    !(lattice.spacing.minCoeff() > 0))
  {
    return Status::failure(
      "the distance field needs at least 2 nodes and a positive spacing on every axis");
  }
  if (values->GetNumberOfTuples() != lattice.nodeCount())
  {
    return Status::failure("the distance field's " + std::string(name) + " array has " +
      std::to_string(values->GetNumberOfTuples()) + " values for " +
      std::to_string(lattice.nodeCount()) + " nodes");
  }
  FieldValues v(values->GetNumberOfTuples());
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    v[i] = static_cast<float>(values->GetTuple1(i));
    if (!std::isfinite(v[i]))
    {
      return Status::failure(
        "the distance field has NaN or infinite values (node " + std::to_string(i) + ")");
    }
  }
  grid = DistanceGrid(lattice, std::move(v));
  return {};
}

vtkSmartPointer<vtkImageData> imageOf(const DistanceGrid& grid, const char* name)
{
  const GridLattice& lattice = grid.lattice();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1);
  image->SetOrigin(lattice.origin.data());
  image->SetSpacing(lattice.spacing.data());
  vtkNew<vtkFloatArray> values;
  values->SetName(name);
  values->SetNumberOfValues(lattice.nodeCount());
  std::copy(grid.values().begin(), grid.values().end(), values->GetPointer(0));
  image->GetPointData()->SetScalars(values);
  return image;
}

TriangleSoup contour(const DistanceGrid& grid, double value)
{
  // Flying Edges writes float points: it contours the grid moved to the origin, and the points
  // move back in double, so that a target far from the origin keeps its cells' precision. It only
  // reads the values: the image views the grid's own (no copy of a large grid).
  const GridLattice& lattice = grid.lattice();
  vtkNew<vtkImageData> image;
  image->SetExtent(0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1);
  image->SetSpacing(lattice.spacing.data());
  vtkNew<vtkFloatArray> values;
  values->SetName("d");
  values->SetArray(const_cast<float*>(grid.values().data()), lattice.nodeCount(), 1);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "d");
  contour->SetValue(0, value);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  TriangleSoup surface;
  surfaceOf(contour->GetOutput(), surface);
  for (Vec3& p : surface.points)
  {
    p += grid.lattice().origin;
  }
  return surface;
}

void setTriangles(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), x[i].data());
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& t : triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    cells->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(cells);
}

Notes addSignStatus(const SignedDistanceResult& result, bool asked, vtkImageData* output)
{
  const std::string status = signStatus(result, asked);
  vtkNew<vtkIntArray> isSigned;
  isSigned->SetName("Signed");
  isSigned->InsertNextValue(result.isSigned ? 1 : 0);
  vtkNew<vtkStringArray> statusArray;
  statusArray->SetName("DistanceStatus");
  statusArray->InsertNextValue(status);
  output->GetFieldData()->AddArray(isSigned);
  output->GetFieldData()->AddArray(statusArray);
  Notes notes;
  if (const auto kind = signNoteKind(result, asked))
  {
    notes.push_back({ *kind, "The distance field is " + status });
  }
  return notes;
}

void report(vtkObject* self, const char* filter, const std::vector<Note>& notes)
{
  for (const Note& note : notes)
  {
    if (note.kind == Note::Warning)
    {
      vtkWarningWithObjectMacro(self, << note.text << ".");
    }
    else
    {
      vtkOutputWindowDisplayText((std::string(filter) + ": " + note.text + ".\n").c_str());
    }
  }
}

} // namespace convert
} // namespace shrinkwrap
