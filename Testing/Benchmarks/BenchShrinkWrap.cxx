// Shrink Wrap beside CGAL's alpha_wrap_3 in one run, on CGAL's bunny00 and armadillo.
//   BenchShrinkWrap <CGAL data/meshes folder> [output folder for the wraps]
// Ours: default parameters, 200 steps, subdivision levels 3..6 (D = 0 and 0.5), and from the offset
// surface (D = 0 and 0.5); the time of the distance field
// (Resolution 120) is shown apart and included in the total. CGAL: alpha = diagonal / 20, / 50, / 100,
// offset = alpha / 30 (CGAL's examples). For each wrap: vertices, one-sided distances from the wrap's
// vertices to the target and from the target's vertices to the wrap (max, as a Hausdorff estimate, in
// percent of the target's diagonal), and the share of triangles with a minimum angle below 20 degrees.
#include "AABBTree.h"
#include "MeshQuality.h"
#include "TestUtilities.h"
#include "vtkMeshSignedDistance.h"
#include "vtkShrinkWrapFilter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <map>

#include <chrono>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point>;
using Clock = std::chrono::steady_clock;
using shrinkwrap::TriangleSoup;
using shrinkwrap::Vec3;

double seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Largest distance from the points of `from` to the surface `to`.
double oneSided(const TriangleSoup& from, const TriangleSoup& to)
{
  const shrinkwrap::AABBTree tree(to);
  double worst = 0;
  for (const Vec3& p : from.points)
  {
    worst = std::max(worst, tree.closestPoint(p).squaredDistance);
  }
  return std::sqrt(worst);
}

double smallAngleShare(const TriangleSoup& soup)
{
  int small = 0;
  for (const auto& t : soup.triangles)
  {
    small += shrinkwrap::triangleQuality(soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]).minAngle < 20;
  }
  return 100.0 * small / soup.triangles.size();
}

void write(const TriangleSoup& soup, const std::string& path)
{
  vtkNew<vtkPoints> points;
  for (const Vec3& p : soup.points)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> triangles;
  for (const auto& t : soup.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetDataModeToBinary(); // inline: this ParaView's reader rejects its own appended base64 here
  writer->Write();
}

void row(const std::string& method, double sdf, double total, const TriangleSoup& wrap, const TriangleSoup& target,
  const std::string& status)
{
  const double diagonal = target.bounds().diagonal();
  std::printf("| %s | %zu | %s | %.3f | %.2f%% | %.2f%% | %.1f%% | %s |\n", method.c_str(), wrap.points.size(),
    sdf > 0 ? (std::to_string(sdf).substr(0, 5)).c_str() : "-", total, 100 * oneSided(wrap, target) / diagonal,
    100 * oneSided(target, wrap) / diagonal, smallAngleShare(wrap), status.c_str());
  std::fflush(stdout);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BenchShrinkWrap <CGAL data/meshes folder> [output folder]\n";
    return 2;
  }
  const std::string folder = argv[1];
  const std::string out = argc > 2 ? argv[2] : "";
  for (const std::string name : { "bunny00", "armadillo" })
  {
    vtkSmartPointer<vtkPolyData> mesh = testing::readOFF(folder + "/" + name + ".off");
    if (!mesh)
    {
      return 1;
    }
    const TriangleSoup target = testing::triangulated(mesh);
    std::printf("\n%s: %zu triangles\n\n| method | vertices | SDF s | total s | wrap->target | target->wrap | min angle < 20 | status |\n"
                "|---|---|---|---|---|---|---|---|\n",
      name.c_str(), target.triangles.size());

    // Ours: the field once (shown apart), then each level with it included in the total.
    auto start = Clock::now();
    vtkNew<vtkMeshSignedDistance> sdf;
    sdf->SetInputData(mesh);
    sdf->SetResolution(120);
    sdf->Update();
    const double sdfSeconds = seconds(start);
    // The defaults (D = 0, paper Fig. 11), then D = 0.5, which edge flips make stable.
    for (const double D : { 0.0, 0.5 })
    {
      for (int level = 3; level <= 6; ++level)
      {
        vtkNew<vtkShrinkWrapFilter> wrap;
        wrap->SetInputData(mesh);
        wrap->SetSubdivisionLevel(level);
        wrap->SetD(D);
        start = Clock::now();
        wrap->Update(); // computes its own field at Resolution 120: the total includes it
        const double total = seconds(start);
        vtkPolyData* result = wrap->GetOutput();
        auto* status = vtkStringArray::SafeDownCast(result->GetFieldData()->GetAbstractArray("Status"));
        row("Shrink Wrap s=" + std::to_string(level) + (D > 0 ? ", D=0.5" : ""), sdfSeconds, total,
          testing::triangulated(result), target, status ? status->GetValue(0) : "none");
        if (!out.empty() && level == 4)
        {
          write(testing::triangulated(result), out + "/" + name + "_shrinkwrap_s4" + (D > 0 ? "_D05" : "") + ".vtp");
        }
      }
    }

    // The Offset Surface start (StartOffset 3, StartClosing 3 cells; vertices follow the field), with
    // D = 0 and D = 0.5.
    for (const double D : { 0.0, 0.5 })
    {
      vtkNew<vtkShrinkWrapFilter> wrap;
      wrap->SetInputData(mesh);
      wrap->SetStartingShape(vtkShrinkWrapFilter::OFFSET_SURFACE);
      wrap->SetD(D);
      start = Clock::now();
      wrap->Update();
      const double total = seconds(start);
      vtkPolyData* result = wrap->GetOutput();
      auto* status = vtkStringArray::SafeDownCast(result->GetFieldData()->GetAbstractArray("Status"));
      row(std::string("Shrink Wrap, offset start") + (D > 0 ? ", D=0.5" : ""), sdfSeconds, total,
        testing::triangulated(result), target, status ? status->GetValue(0) : "none");
      if (!out.empty())
      {
        write(testing::triangulated(result), out + "/" + name + "_shrinkwrap_offset" + (D > 0 ? "_D05" : "") + ".vtp");
      }
    }

    // CGAL's alpha wrap on the same triangles.
    std::vector<Point> points;
    for (const Vec3& p : target.points)
    {
      points.emplace_back(p.x(), p.y(), p.z());
    }
    std::vector<std::array<std::size_t, 3>> faces;
    for (const auto& t : target.triangles)
    {
      faces.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]), static_cast<std::size_t>(t[2]) });
    }
    const double diagonal = target.bounds().diagonal();
    for (const int divisor : { 20, 50, 100 })
    {
      const double alpha = diagonal / divisor, offset = alpha / 30;
      CgalMesh wrapped;
      start = Clock::now();
      CGAL::alpha_wrap_3(points, faces, alpha, offset, wrapped);
      const double total = seconds(start);
      TriangleSoup soup;
      std::map<CgalMesh::Vertex_index, int> index;
      for (auto v : wrapped.vertices())
      {
        index[v] = static_cast<int>(soup.points.size());
        const Point& p = wrapped.point(v);
        soup.points.emplace_back(p.x(), p.y(), p.z());
      }
      for (auto f : wrapped.faces())
      {
        std::array<int, 3> tri{};
        int k = 0;
        for (auto v : CGAL::vertices_around_face(wrapped.halfedge(f), wrapped))
        {
          tri[k++ % 3] = index[v];
        }
        soup.triangles.push_back(tri);
      }
      row("alpha_wrap_3 diag/" + std::to_string(divisor), 0, total, soup, target, "ok");
      if (!out.empty() && divisor == 50)
      {
        write(soup, out + "/" + name + "_alphawrap_50.vtp");
      }
    }
  }
  return 0;
}
