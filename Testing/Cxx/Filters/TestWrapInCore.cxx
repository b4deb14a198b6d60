// Shrink Wrap through the core alone, without the filter or its pipeline (Wrap.h: the target made,
// planned, its fields, start and session, and the steps), gives the filter's surface bit for bit:
// on a mesh, on its points, from the icosphere, and on a given distance field. The contour handed
// to the core is the filters' (marching cubes, VTKConversions.h), as the filter hands it.
#include "TestUtilities.h"
#include "vtkInputGeometry.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include "Wrap/Wrap.h"

#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkSuperquadricSource.h>
#include <vtkTriangleFilter.h>

#include <functional>

namespace
{
using namespace shrinkwrap;

vtkSmartPointer<vtkPolyData> roundedBox()
{
  vtkNew<vtkSuperquadricSource> source;
  source->SetScale(1.0, 0.7, 0.5);
  source->SetThetaRoundness(0.3);
  source->SetPhiRoundness(0.3);
  source->SetThetaResolution(32);
  source->SetPhiResolution(32);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

// The filter's wrap and the core's, of `target` with the same settings.
void same(const char* what, vtkPolyData* target,
  const std::function<void(vtkShrinkWrapFilter*)>& set, vtkImageData* field = nullptr)
{
  vtkNew<vtkShrinkWrapFilter> filter;
  filter->SetInputData(target);
  if (field)
  {
    filter->SetInputData(1, field);
  }
  set(filter);
  filter->Update();
  TriangleSoup byFilter;
  convert::surfaceOf(filter->GetOutput(), byFilter);

  // The same through the core, from the settings the filter's properties give.
  vtkNew<vtkShrinkWrapFilter> properties;
  set(properties);
  const WrapSettings settings = properties->CoreSettings();
  convert::SoupCounts counts;
  const bool points = properties->GetInputGeometry() == vtkInputGeometry::POINTS;
  WrapTarget core;
  const Status made = points ? makeTarget({}, convert::pointsOf<PointList>(target), core)
                             : makeTarget(convert::soupOf({ target }, counts), {}, core);
  if (field)
  {
    DistanceGrid grid;
    convert::gridOf(field, "SignedDistance", grid);
    core.fieldLattice = grid.lattice();
    core.field = std::make_shared<const DistanceGrid>(grid);
  }
  WrapResult result;
  const Status wrapped = made ? wrap(core, settings, convert::contour, result) : made;
  SW_CHECK(wrapped, what << ": the core wraps: " << wrapped.message());
  std::printf("%s: the filter's wrap %zu vertices, the core's %zu\n", what, byFilter.points.size(),
    result.surface.points.size());
  SW_CHECK(!byFilter.points.empty() && result.surface.points == byFilter.points &&
      result.surface.triangles == byFilter.triangles,
    what << ": the core's surface is the filter's, bit for bit");
}
} // namespace

int TestWrapInCore(int, char*[])
{
  const vtkSmartPointer<vtkPolyData> box = roundedBox();
  same("a mesh at the defaults", box, [](vtkShrinkWrapFilter*) {});
  same("its points", box,
    [](vtkShrinkWrapFilter* f) { f->SetInputGeometry(vtkInputGeometry::POINTS); });
  same("from the icosphere", box, [](vtkShrinkWrapFilter* f) {
    f->SetStartingShape(vtkShrinkWrapFilter::ICOSPHERE);
    f->SetNumberOfSteps(60);
  });
  vtkNew<vtkMeshSignedDistance> distance;
  distance->SetInputData(box);
  distance->SetResolution(64);
  distance->Update();
  same(
    "on Mesh Signed Distance's field", box, [](vtkShrinkWrapFilter*) {}, distance->GetOutput());
  return testing::finish("TestWrapInCore");
}
