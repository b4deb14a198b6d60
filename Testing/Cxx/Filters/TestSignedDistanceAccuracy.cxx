// Accuracy of Mesh Signed Distance against brute-force exact distances (every node x every
// triangle) and winding-number signs, on small closed meshes built here (issue #2 bars).
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"

#include <vtkAppendPolyData.h>
#include <vtkCubeSource.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkSphereSource.h>
#include <vtkStripper.h>

namespace
{
vtkSmartPointer<vtkPolyData> sphere(double cx, double r)
{
  vtkNew<vtkSphereSource> s;
  s->SetCenter(cx, 0.1, -0.2);
  s->SetRadius(r);
  s->SetThetaResolution(40);
  s->SetPhiResolution(24);
  s->Update();
  return s->GetOutput();
}

// A hexagonal prism: two hexagons and six quads, with points shared by index.
vtkSmartPointer<vtkPolyData> hexagonalPrism()
{
  vtkNew<vtkPoints> points;
  for (int level = 0; level < 2; ++level)
  {
    for (int k = 0; k < 6; ++k)
    {
      const double a = k * vtkMath::Pi() / 3;
      points->InsertNextPoint(std::cos(a), 0.8 * std::sin(a), level ? 0.7 : -0.7);
    }
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType bottom[6] = { 5, 4, 3, 2, 1, 0 }, top[6] = { 6, 7, 8, 9, 10, 11 };
  polys->InsertNextCell(6, bottom);
  polys->InsertNextCell(6, top);
  for (vtkIdType k = 0; k < 6; ++k)
  {
    const vtkIdType quad[4] = { k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k };
    polys->InsertNextCell(4, quad);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

vtkSmartPointer<vtkPolyData> torus()
{
  vtkNew<vtkParametricTorus> shape;
  shape->SetRingRadius(1.0);
  shape->SetCrossSectionRadius(0.35);
  vtkNew<vtkParametricFunctionSource> source; // seams carry duplicated points
  source->SetParametricFunction(shape);
  source->SetUResolution(48);
  source->SetVResolution(24);
  source->Update();
  return source->GetOutput();
}

vtkSmartPointer<vtkPolyData> cube()
{
  vtkNew<vtkCubeSource> source; // quads, four copies of every corner
  source->SetXLength(1.0);
  source->SetYLength(0.6);
  source->SetZLength(0.8);
  source->Update();
  return source->GetOutput();
}

// The sphere as triangle strips only.
vtkSmartPointer<vtkPolyData> strips()
{
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(sphere(0, 1));
  stripper->Update();
  return stripper->GetOutput();
}

vtkSmartPointer<vtkPolyData> twoComponents()
{
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(sphere(-1.0, 0.5));
  append->AddInputData(sphere(0.8, 0.3));
  append->Update();
  return append->GetOutput();
}

void check(
  const std::string& name, vtkPolyData* mesh, int resolution, int sweep, double offsetFactor = 1.0)
{
  vtkNew<vtkMeshSignedDistance> filter;
  filter->SetInputData(mesh);
  filter->SetResolution(resolution);
  filter->SetOffsetFactor(offsetFactor);
  filter->SetSweepMethod(sweep);
  filter->Update();
  vtkImageData* image = filter->GetOutput();
  SW_CHECK(image->GetFieldData()->GetArray("Signed") &&
      image->GetFieldData()->GetArray("Signed")->GetTuple1(0) == 1,
    name << ": a closed mesh gives a signed field");
  const testing::FieldErrors errors = testing::compareWithReference(
    image, testing::triangulated(mesh), /*brute=*/true, /*checkSign=*/true);
  if (sweep == vtkMeshSignedDistance::CLOSEST_POINT)
  {
    testing::checkAccuracy(name, errors, true);
  }
  else
  {
    // The paper's Eikonal sweep is first order: only the band and the sign are held to the bars.
    testing::printErrors(name + " (Eikonal)", errors);
    SW_CHECK(errors.bandMaxError <= 1e-5, name << " (Eikonal): band exact");
    SW_CHECK(errors.signErrors == 0, name << " (Eikonal): no sign errors");
    SW_CHECK(errors.maxError <= 3.0, name << " (Eikonal): max error within 3 h");
  }
}
} // namespace

int TestSignedDistanceAccuracy(int, char*[])
{
  check("sphere", sphere(0, 1), 48, vtkMeshSignedDistance::CLOSEST_POINT);
  check("cube (quads)", cube(), 48, vtkMeshSignedDistance::CLOSEST_POINT);
  check("torus (seams)", torus(), 48, vtkMeshSignedDistance::CLOSEST_POINT);
  // A box tight around the torus: the seams' slivers (1e-15 wide) are then the closest triangles of
  // far nodes, whose sides their rounding-noise normals once turned.
  check("torus (seams), tight box", torus(), 40, vtkMeshSignedDistance::CLOSEST_POINT, 0.1);
  check("torus (seams), tight box", torus(), 40, vtkMeshSignedDistance::EIKONAL, 0.1);
  check("two components", twoComponents(), 48, vtkMeshSignedDistance::CLOSEST_POINT);
  vtkSmartPointer<vtkPolyData> stripped = strips();
  SW_CHECK(stripped->GetNumberOfStrips() > 0 && stripped->GetNumberOfPolys() == 0,
    "the stripped sphere has strips only");
  check("sphere as triangle strips", stripped, 48, vtkMeshSignedDistance::CLOSEST_POINT);
  check("hexagonal prism (n-gons)", hexagonalPrism(), 48, vtkMeshSignedDistance::CLOSEST_POINT);
  check("torus", torus(), 40, vtkMeshSignedDistance::EIKONAL);
  return testing::finish("TestSignedDistanceAccuracy");
}
