// Between VTK's data and the core's, for both filters: polygon meshes to a triangle soup or
// surface, image data to a distance grid and back, contours of a grid (VTK's Flying Edges), and the
// wrap's output surface with its arrays.
#ifndef ShrinkWrap_VTKConversions_h
#define ShrinkWrap_VTKConversions_h

#include "Common/Notes.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/DistanceGrid.h"
#include "Distance/PointTree.h"
#include "Distance/SignedDistance.h"
#include "Distance/TargetDistance.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"
#include "Wrap/WrapPlan.h"

#include <vtkCompositeDataSet.h>
#include <vtkDemandDrivenPipeline.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkDataObject;
class vtkObject;
class vtkDataSet;
class vtkImageData;
class vtkPolyData;

namespace shrinkwrap
{
namespace convert
{

// The polygon meshes of an input: itself, or the leaves of a composite dataset. A dataset of
// another kind with cells (an unstructured grid, an image) gives its outer surface, as Extract
// Surface does.
struct PolygonMeshes
{
  std::vector<vtkPolyData*> meshes;
  std::vector<vtkSmartPointer<vtkPolyData>>
    extracted;               // the surfaces made here, which `meshes` holds
  std::string extractedFrom; // the kinds of data they were made of ("vtkUnstructuredGrid", ...)
};
PolygonMeshes polygonMeshes(vtkDataObject* input);

// Every point of every leaf of an input, for an input measured as points: Points is a
// std::vector<Vec3> (Mesh Signed Distance's soup) or a PointList (a wrap's cloud).
template <typename Points>
Points pointsOf(vtkDataObject* input);

// The points of a mesh that none of its polygons or strips uses (its vertices' and lines' points,
// and points of no cell): the points beside its surface.
template <typename Points>
Points loosePointsOf(vtkPolyData* mesh);

// Which parts of an input a filter takes, by its InputGeometry (0 automatic: the polygons when it
// has any, else the points; 1 polygons, 2 points, 3 both).
struct Geometry
{
  bool polygons = false;
  bool points = false;
};
Geometry chooseGeometry(int inputGeometry, bool hasPolygons);
const char* geometryName(int inputGeometry); // for PrintSelf

// What a soup was made of besides its triangles.
struct SoupCounts
{
  long long badCells = 0; // cells naming points that do not exist (left out)
  long long lines = 0;    // lines and vertices, which have no inside (left out)
  long long vertices = 0;
};

// The paper's triangle soup of meshes, one after the other: polygons of any size (ear-cut by
// vtkPolygon when n > 3, a fan where that fails) and strips. `cells`, if given, receives the cell
// each triangle comes of, numbered over the meshes one after the other (a mesh's cells after the
// previous meshes' cells).
TriangleSoup soupOf(const std::vector<vtkPolyData*>& meshes, SoupCounts& counts,
  std::vector<vtkIdType>* cells = nullptr);

// A mesh of triangles only as a surface; fails for other polygons, strips, no triangles, invalid
// point ids or points that are not finite.
Status surfaceOf(vtkPolyData* mesh, TriangleSoup& surface);

// Bounds of the points that polygons and strips use: the surface, without stray points or lines.
Box surfaceBounds(const std::vector<vtkPolyData*>& meshes);
// Bounds of all the points of a dataset.
Box boundsOf(vtkDataSet* data);
// Box::around(pointsOf(input)), without the copy.
Box pointBounds(vtkDataObject* input);

// The nodes of an image (its extent, origin and spacing) as a lattice.
GridLattice latticeOf(vtkImageData* image);
// The point array `name` of an image as a grid: one component, at least 2 nodes and a positive
// spacing on every axis, finite values.
Status gridOf(vtkImageData* image, const char* name, DistanceGrid& grid);
// A grid as an image whose point array `name` holds its values.
vtkSmartPointer<vtkImageData> imageOf(const DistanceGrid& grid, const char* name);

// Marching cubes (vtkFlyingEdges3D) of a grid at one value: the core's Contour (ContourTopology.h).
TriangleSoup contour(const DistanceGrid& grid, double value);

// Points (as doubles) and triangles as `output`'s geometry.
void setTriangles(const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
  vtkPolyData* output);

// Field data Signed (1 or 0) and DistanceStatus (the sentence of signStatus) of a field; a warning
// note when the sign is one a user should hear of (signNoteKind).
Notes addSignStatus(const SignedDistanceResult& result, bool asked, vtkImageData* output);

// Notes as a filter's messages: warnings as its warnings, the others in the output messages
// prefixed by `filter` ("Shrink Wrap: ...").
void report(vtkObject* self, const char* filter, const std::vector<Note>& notes);

// A filter's output object on `port`, when `request` asks for it (REQUEST_DATA_OBJECT; then
// true): a composite of the same kind as `composite`, or, without one, a `Leaf`; the output is
// kept when it is of that kind already.
template <typename Leaf>
bool makeOutput(vtkInformation* request, vtkInformationVector* outputs,
  vtkCompositeDataSet* composite, int port = 0)
{
  if (!request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return false;
  }
  vtkInformation* outInfo = outputs->GetInformationObject(port);
  vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
  if (composite ? !output || std::string(output->GetClassName()) != composite->GetClassName()
                : !Leaf::SafeDownCast(output))
  {
    vtkSmartPointer<vtkDataObject> made = composite
      ? vtkSmartPointer<vtkDataObject>::Take(composite->NewInstance())
      : vtkSmartPointer<vtkDataObject>(vtkSmartPointer<Leaf>::New());
    outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return true;
}

} // namespace convert
} // namespace shrinkwrap

#endif
