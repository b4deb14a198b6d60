// Shrink Wrap with its default parameters on real meshes (CGAL's data set, Debian libcgal-demo) and the
// paper's "bent chair" (Fig. 3: a deformed cube with holes), at subdivision levels 3 and 4, 200 steps:
// no failure, a closed 2-manifold in one piece; on bunny00 and armadillo the median |d| within one cell
// and fewer than 2% of triangles with a minimum angle below 20 degrees (issue #4's bar; CGAL's alpha
// wrap at similar vertex counts has 5-17%). The 90th percentile of |d| is reported for every mesh, and
// the other meshes' figures too. The same with D = 0.5.
// Argument: the folder holding CGAL's data/meshes/*.off.
#include "SurfaceMesh.h"
#include "TestUtilities.h"
#include "vtkShrinkWrapFilter.h"

#include <vtkCellData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkStringArray.h>

#include <chrono>

namespace
{
// A cube of 6 x 6 quads per face, without the middle 2 x 2 quads of its four side faces, bent.
vtkSmartPointer<vtkPolyData> bentChair()
{
  const int n = 6;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  auto corner = [&](int face, int u, int v) {
    const double a = -0.5 + static_cast<double>(u) / n, b = -0.5 + static_cast<double>(v) / n;
    double p[3];
    switch (face)
    {
      case 0: p[0] = -0.5; p[1] = b; p[2] = a; break;
      case 1: p[0] = 0.5; p[1] = a; p[2] = b; break;
      case 2: p[0] = a; p[1] = -0.5; p[2] = b; break;
      case 3: p[0] = b; p[1] = 0.5; p[2] = a; break;
      case 4: p[0] = b; p[1] = a; p[2] = -0.5; break;
      default: p[0] = a; p[1] = b; p[2] = 0.5; break;
    }
    // The bend: the top leans over, the seat sags.
    p[0] += 0.35 * (p[2] + 0.5) * (p[2] + 0.5);
    p[2] -= 0.2 * (0.25 - p[0] * p[0]);
    return points->InsertNextPoint(p);
  };
  for (int face = 0; face < 6; ++face)
  {
    for (int u = 0; u < n; ++u)
    {
      for (int v = 0; v < n; ++v)
      {
        const bool hole = face < 4 && u >= 2 && u < 4 && v >= 2 && v < 4;
        if (!hole)
        {
          const vtkIdType q[4] = { corner(face, u, v), corner(face, u + 1, v), corner(face, u + 1, v + 1),
            corner(face, u, v + 1) };
          quads->InsertNextCell(4, q);
        }
      }
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points); // duplicated points along face seams: the triangle soup welds them
  mesh->SetPolys(quads);
  return mesh;
}

struct Figures
{
  double median = 0, p90 = 0, smallAngles = 0, seconds = 0;
  bool ok = false, closed = false;
  int pieces = 0;
};

Figures wrap(vtkPolyData* target, int level, double D)
{
  vtkNew<vtkShrinkWrapFilter> filter;
  filter->SetInputData(target);
  filter->SetSubdivisionLevel(level);
  filter->SetD(D);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  Figures f;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* out = filter->GetOutput();
  auto* status = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("Status"));
  f.ok = status && status->GetValue(0) == "ok" && out->GetNumberOfPoints() > 0;
  if (out->GetNumberOfPoints() == 0)
  {
    return f;
  }
  // The field's cell: 3.3 times the largest side of the target over Resolution 120.
  double b[6];
  target->GetBounds(b);
  const double h = 3.3 * std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] }) / 120;
  std::vector<double> d;
  vtkDataArray* distance = out->GetPointData()->GetArray("Distance");
  for (vtkIdType i = 0; i < distance->GetNumberOfTuples(); ++i)
  {
    d.push_back(std::abs(distance->GetTuple1(i)) / h);
  }
  std::sort(d.begin(), d.end());
  f.median = d[d.size() / 2];
  f.p90 = d[d.size() * 9 / 10];
  vtkDataArray* angles = out->GetCellData()->GetArray("MinAngle");
  int small = 0;
  for (vtkIdType t = 0; t < angles->GetNumberOfTuples(); ++t)
  {
    small += angles->GetTuple1(t) < 20.0;
  }
  f.smallAngles = 100.0 * small / angles->GetNumberOfTuples();
  std::vector<shrinkwrap::Vec3> x(out->GetNumberOfPoints());
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    out->GetPoint(i, x[i].data());
  }
  shrinkwrap::SurfaceMesh mesh;
  std::string error;
  f.closed = shrinkwrap::SurfaceMesh::build(x, testing::triangulated(out).triangles, mesh, error);
  vtkNew<vtkPolyDataConnectivityFilter> pieces;
  pieces->SetInputData(out);
  pieces->SetExtractionModeToAllRegions();
  pieces->Update();
  f.pieces = pieces->GetNumberOfExtractedRegions();
  return f;
}
} // namespace

int TestShrinkWrapCGALMeshes(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestShrinkWrapCGALMeshes <CGAL data/meshes folder>" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string folder = argv[1];
  std::printf("%-26s %-3s %-8s %-12s %-14s %-14s %-8s\n", "mesh", "s", "status", "median |d|", "90th pct |d|",
    "min angle<20", "seconds");
  for (const std::string name : { "bunny00", "armadillo", "elephant-with-holes", "knot1", "bent chair" })
  {
    vtkSmartPointer<vtkPolyData> target = name == "bent chair" ? bentChair() : testing::readOFF(folder + "/" + name + ".off");
    SW_CHECK(target != nullptr, name << " found in " << folder);
    if (!target)
    {
      continue;
    }
    // D = 0 is the default (paper Fig. 11); D = 0.5, stable with edge flips, is what the README
    // recommends for closer wraps, so it is held to the same bars.
    for (const double D : { 0.0, 0.5 })
    {
      for (int level : { 3, 4 })
      {
        const Figures f = wrap(target, level, D);
        const std::string label = name + (D > 0 ? " D=0.5" : "");
        std::printf("%-26s %-3d %-8s %6.2f h     %6.2f h       %6.1f %%       %.2f\n", label.c_str(), level,
          f.ok ? "ok" : "FAILED", f.median, f.p90, f.smallAngles, f.seconds);
        SW_CHECK(f.ok, label << " s=" << level << ": 200 steps without failure");
        SW_CHECK(f.closed && f.pieces == 1, label << " s=" << level << ": a closed 2-manifold in one piece");
        if (name == "bunny00" || name == "armadillo")
        {
          SW_CHECK(f.median <= 1.0, label << " s=" << level << ": median |d| within one cell");
          SW_CHECK(f.smallAngles < 2.0,
            label << " s=" << level << ": fewer than 2% of triangles with an angle below 20 degrees");
        }
      }
    }
  }
  return testing::finish("TestShrinkWrapCGALMeshes");
}
