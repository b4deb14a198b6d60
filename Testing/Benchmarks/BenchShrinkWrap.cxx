// Shrink Wrap beside CGAL's alpha_wrap_3 in one run, on CGAL meshes with thin parts, fingers and
// legs, holes, an open mesh and CAD parts with sharp edges (issue #10).
//   BenchShrinkWrap <CGAL data/meshes folder> [--out folder] [--meshes a,b,...] [--set Name=value
//   ...]
//     [--points N [--noise percent] [--draw K] [--ramp R]] [--repeat N]  (issue #13: N points
//     sampled on each mesh wrapped instead)
// Ours: the defaults, and Target Edge Length diagonal / 25 and / 100 (the field's Resolution
// follows L, so that a cell stays below L); the time includes the distance field. CGAL: alpha =
// diagonal / 20, / 50, / 100, offset = alpha / 30 (CGAL's examples). Every wrap is judged the same
// way
// (../Cxx/WrapEvaluation.h): 100,000 points sampled on each surface plus its vertices, one-sided
// distances to the other surface (mean and largest, percent of the target's diagonal), crossing
// triangle pairs (ours, and CGAL's does_self_intersect), closed and manifold, genus, the share of
// triangles with a minimum angle below 20 degrees. --set applies a property to our wraps (D, C, C1,
// C2, TimeStep, NumberOfSteps, Resolution, StartOffset, GapSize, TargetEdgeLength, ShortestEdge and
// LongestEdge (EdgeLengthRange), Remeshing,
// StartingShape, SubdivisionLevel, InitialRelaxation, CloseHoles, CoverRims, FitFacets), for
// tuning. --time-only runs our defaults alone and prints their time and vertex count, without
// evaluation or peers (for profiling); with --points, our wrap of the points evaluated, without
// peers. --no-reconstruction leaves out vtkSurfaceReconstructionFilter (the slowest peer of
// --points) for a quicker run beside alpha wrap alone. --repeat N runs every wrap N times and
// reports the fastest (this machine's times vary by 20% from run to run; the fastest of a few is
// the one least disturbed), each of ours by a new filter, so that none reuses another's work.
// --sizes N,... (issue #62's scaling) replaces both sides' sizes: ours at Target Edge Length = Gap
// Size = diagonal / N with Resolution 1.5 N, alpha wrap at alpha = diagonal / N; --only ours|alpha
// runs one side, so that a fresh process per run gives that run's peak resident memory (printed
// after each row).
// --draw K samples the points (and their noise) with other seeds: a largest distance depends on
// where the points fall, and one draw cannot tell a trend from luck. --ramp R makes the points'
// density fall R times along x (a scan's far side): a sample is kept with a probability from 1 at
// the box's largest x to 1 / R at its smallest.
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkShrinkWrapFilter.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>
#include <CGAL/version.h>

#include <vtkCellArray.h>
#include <vtkContourFilter.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkSurfaceReconstructionFilter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point>;
using Clock = std::chrono::steady_clock;
// The peer's rows name its CGAL: 5.5 (Debian 12) or 6.0 (BenchShrinkWrapCGAL6).
const std::string kAlphaWrap = std::string("alpha_wrap_3 (CGAL ") + CGAL_VERSION_STR + ")";
using shrinkwrap::TriangleSoup;
using shrinkwrap::Vec3;

double seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The fastest of `repeats` runs of run(), in seconds; what the last run made is kept.
template <typename Run>
double fastestOf(int repeats, Run&& run)
{
  double fastest = std::numeric_limits<double>::infinity();
  for (int r = 0; r < std::max(repeats, 1); ++r)
  {
    const auto start = Clock::now();
    run();
    fastest = std::min(fastest, seconds(start));
  }
  return fastest;
}

// The process's peak resident memory so far, as a line under a row (--sizes).
void peakRow()
{
  std::printf("peak resident memory: %.0f MB\n", testing::peakRssKiB() / 1024.0);
}

void write(const TriangleSoup& soup, const std::string& path)
{
  vtkNew<vtkPolyData> mesh;
  shrinkwrap::convert::setTriangles(soup.points, soup.triangles, mesh);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer
    ->SetDataModeToBinary(); // inline: this ParaView's reader rejects its own appended base64 here
  writer->Write();
}

CgalMesh cgalMesh(const TriangleSoup& soup)
{
  CgalMesh mesh;
  std::vector<CgalMesh::Vertex_index> v;
  for (const Vec3& p : soup.points)
  {
    v.push_back(mesh.add_vertex(Point(p.x(), p.y(), p.z())));
  }
  for (const auto& t : soup.triangles)
  {
    mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  }
  return mesh;
}

TriangleSoup soupOf(const CgalMesh& mesh)
{
  TriangleSoup soup;
  std::map<CgalMesh::Vertex_index, int> index;
  for (auto v : mesh.vertices())
  {
    index[v] = static_cast<int>(soup.points.size());
    const Point& p = mesh.point(v);
    soup.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : mesh.faces())
  {
    std::array<int, 3> tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      tri[k++ % 3] = index[v];
    }
    soup.triangles.push_back(tri);
  }
  return soup;
}

void header()
{
  std::printf("| method | vertices | time s | mean w→t | mean t→w | max w→t | max t→w | self-int. "
              "pairs (CGAL) | closed manifold | genus | angles < 20° | status |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void row(const std::string& method, double time, const TriangleSoup& wrap,
  const TriangleSoup& target, const std::string& status)
{
  const testing::WrapFigures f = testing::evaluateWrap(wrap, target);
  bool cgalSelf = false;
  if (!wrap.triangles.empty())
  {
    const CgalMesh mesh = cgalMesh(wrap);
    cgalSelf = CGAL::Polygon_mesh_processing::does_self_intersect(mesh);
  }
  std::printf(
    "| %s | %d | %.2f | %.3f%% | %.3f%% | %.2f%% | %.2f%% | %lld (%s) | %s | %d | %.2f%% | %s |\n",
    method.c_str(), f.vertices, time, f.wrapToTarget.mean, f.targetToWrap.mean,
    f.wrapToTarget.largest, f.targetToWrap.largest, f.selfIntersections, cgalSelf ? "yes" : "no",
    f.closedManifold ? "yes" : "no", f.genus, f.smallAngles, status.c_str());
  std::fflush(stdout);
}

using Setter = std::function<void(vtkShrinkWrapFilter*, double)>;
const std::map<std::string, Setter>& setters();

// A new Shrink Wrap of `input` with the --set properties: a fresh filter per run, so that no run
// reuses another's cached work.
vtkSmartPointer<vtkShrinkWrapFilter> configuredWrap(
  vtkDataObject* input, const std::vector<std::pair<std::string, double>>& sets)
{
  auto wrap = vtkSmartPointer<vtkShrinkWrapFilter>::New();
  wrap->SetInputData(input);
  for (const auto& s : sets)
  {
    setters().at(s.first)(wrap, s.second);
  }
  return wrap;
}

// How a benchmark's cloud is sampled (the options --points, --noise, --draw and --ramp).
struct CloudSampling
{
  int count = 0;    // points
  double noise = 0; // Gaussian noise, % of the diagonal
  int draw = 0;     // another sample of the points and their noise (0: the usual one)
  double ramp = 1;  // density falling this many times along x (1: uniform)
};

// `sampling.count` points sampled on the target by area (seeded), kept with a probability falling
// `sampling.ramp` times along x, with Gaussian noise.
std::vector<Vec3> sampledCloud(const TriangleSoup& target, const CloudSampling& sampling)
{
  const shrinkwrap::Box box = target.bounds();
  const double ramp = std::max(1.0, sampling.ramp);
  // Enough samples that the kept ones reach the count: at least one in `ramp` is kept.
  const int drawn = static_cast<int>(std::ceil(sampling.count * ramp));
  std::vector<Vec3> samples = testing::samplePoints(target, drawn, 7 + sampling.draw);
  samples.erase(samples.begin(),
    samples.begin() + static_cast<std::ptrdiff_t>(target.points.size())); // samples only
  std::mt19937_64 random(11 + sampling.draw);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Vec3> cloud;
  const double width = std::max(box.max.x() - box.min.x(), std::numeric_limits<double>::min());
  for (const Vec3& p : samples)
  {
    const double keep = 1 / ramp + (1 - 1 / ramp) * (p.x() - box.min.x()) / width;
    if (static_cast<int>(cloud.size()) < sampling.count && (ramp == 1 || unit(random) < keep))
    {
      cloud.push_back(p);
    }
  }
  std::normal_distribution<double> gauss(0, sampling.noise / 100 * box.diagonal());
  for (Vec3& p : cloud)
  {
    p += sampling.noise > 0 ? Vec3(gauss(random), gauss(random), gauss(random)) : Vec3::Zero();
  }
  return cloud;
}

// Points sampled on the target (sampledCloud), wrapped by ours at its defaults, alpha_wrap_3 on the
// same points (alpha = diagonal / 20, / 50, / 100, offset alpha / 30) and VTK's
// vtkSurfaceReconstructionFilter + contour at 0; every wrap judged against the original mesh (the
// truth). With `out`, the cloud and the wraps are written as <out>_target.vtp,
// <out>_shrinkwrap.vtp, <out>_alphawrap_<divisor>.vtp.
void cloudRows(const TriangleSoup& target, const CloudSampling& sampling,
  const std::vector<std::pair<std::string, double>>& sets, const std::string& out, bool peers,
  bool withReconstruction, int repeats)
{
  const double diagonal = target.bounds().diagonal();
  const std::vector<Vec3> cloud = sampledCloud(target, sampling);
  std::printf("(%zu points, noise %.2f%% of the diagonal%s", cloud.size(), sampling.noise,
    sampling.draw > 0 ? (", draw " + std::to_string(sampling.draw)).c_str() : "");
  std::printf(sampling.ramp > 1 ? ", density falling %g times along x)\n" : ")\n", sampling.ramp);
  vtkNew<vtkPoints> points;
  for (const Vec3& p : cloud)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  if (!out.empty())
  {
    vtkNew<vtkPolyData> shown; // the cloud with a vertex per point, so that ParaView draws it
    shown->SetPoints(points);
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      vertices->InsertNextCell(1, &i);
    }
    shown->SetVerts(vertices);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(shown);
    writer->SetFileName((out + "_target.vtp").c_str());
    writer->SetDataModeToBinary();
    writer->Write();
  }
  {
    vtkSmartPointer<vtkShrinkWrapFilter> wrap;
    const double total = fastestOf(repeats, [&] {
      wrap = configuredWrap(input, sets);
      wrap->Update();
    });
    auto* status =
      vtkStringArray::SafeDownCast(wrap->GetOutput()->GetFieldData()->GetAbstractArray("Status"));
    const TriangleSoup soup = testing::triangulated(wrap->GetOutput());
    row("Shrink Wrap, defaults", total, soup, target, status ? status->GetValue(0) : "none");
    if (!out.empty())
    {
      write(soup, out + "_shrinkwrap.vtp");
    }
  }
  if (!peers)
  {
    return;
  }
  std::vector<Point> cgalPoints;
  for (const Vec3& p : cloud)
  {
    cgalPoints.emplace_back(p.x(), p.y(), p.z());
  }
  for (const int divisor : { 20, 50, 100 })
  {
    const double alpha = diagonal / divisor, offset = alpha / 30;
    CgalMesh wrapped;
    const double total = fastestOf(repeats, [&] {
      wrapped.clear();
      CGAL::alpha_wrap_3(cgalPoints, alpha, offset, wrapped);
    });
    row(kAlphaWrap + " diag/" + std::to_string(divisor), total, soupOf(wrapped), target, "ok");
    if (!out.empty())
    {
      write(soupOf(wrapped), out + "_alphawrap_" + std::to_string(divisor) + ".vtp");
    }
  }
  if (withReconstruction)
  {
    vtkNew<vtkSurfaceReconstructionFilter> reconstruction;
    reconstruction->SetInputData(input);
    vtkNew<vtkContourFilter> contour;
    contour->SetInputConnection(reconstruction->GetOutputPort());
    contour->SetValue(0, 0.0);
    const double total = fastestOf(repeats, [&] {
      reconstruction->Modified();
      contour->Update();
    });
    // The reconstruction's grid is in its own index space scaled to the points' bounds: the contour
    // is already in the input's coordinates (vtkSurfaceReconstructionFilter sets origin and
    // spacing).
    row("vtkSurfaceReconstructionFilter + contour", total,
      testing::triangulated(contour->GetOutput()), target, "ok");
  }
}
const std::map<std::string, Setter>& setters()
{
  static const std::map<std::string, Setter> s = {
    { "D", [](vtkShrinkWrapFilter* w, double v) { w->SetConcavityPush(v); } },
    { "C", [](vtkShrinkWrapFilter* w, double v) { w->SetAdvectionSpeed(v); } },
    { "C1", [](vtkShrinkWrapFilter* w, double v) { w->SetSmoothing(v); } },
    { "C2", [](vtkShrinkWrapFilter* w, double v) { w->SetSmoothingFalloff(v); } },
    { "TimeStep", [](vtkShrinkWrapFilter* w, double v) { w->SetTimePerStep(v); } },
    { "NumberOfSteps",
      [](vtkShrinkWrapFilter* w, double v) { w->SetNumberOfSteps(static_cast<int>(v)); } },
    { "Resolution",
      [](vtkShrinkWrapFilter* w, double v) { w->SetResolution(static_cast<int>(v)); } },
    { "StartOffset", [](vtkShrinkWrapFilter* w, double v) { w->SetStartOffsetInCells(v); } },
    { "GapSize", [](vtkShrinkWrapFilter* w, double v) { w->SetGapSize(v); } },
    { "TargetEdgeLength", [](vtkShrinkWrapFilter* w, double v) { w->SetTargetEdgeLength(v); } },
    { "ShortestEdge",
      [](vtkShrinkWrapFilter* w, double v) {
        w->SetEdgeLengthRange(v, w->GetEdgeLengthRange()[1]);
      } },
    { "LongestEdge",
      [](vtkShrinkWrapFilter* w, double v) {
        w->SetEdgeLengthRange(w->GetEdgeLengthRange()[0], v);
      } },
    { "Remeshing", [](vtkShrinkWrapFilter* w, double v) { w->SetRemeshing(v != 0); } },
    { "StartingShape",
      [](vtkShrinkWrapFilter* w, double v) { w->SetStartingShape(static_cast<int>(v)); } },
    { "CloseHoles", [](vtkShrinkWrapFilter* w, double v) { w->SetCloseHoles(v != 0); } },
    { "CoverRims", [](vtkShrinkWrapFilter* w, double v) { w->SetCoverRims(v != 0); } },
    { "FitFacets", [](vtkShrinkWrapFilter* w, double v) { w->SetFitFacets(v != 0); } },
    { "InitialRelaxation",
      [](vtkShrinkWrapFilter* w, double v) { w->SetInitialRelaxation(static_cast<int>(v)); } },
    { "SubdivisionLevel",
      [](vtkShrinkWrapFilter* w, double v) { w->SetSubdivisionLevel(static_cast<int>(v)); } },
  };
  return s;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BenchShrinkWrap <CGAL data/meshes folder> [--out folder] [--meshes a,b] "
                 "[--set Name=value] [--points N [--noise percent] [--draw K] [--ramp R]] "
                 "[--repeat N] [--defaults-only] [--time-only] [--no-reconstruction]\n";
    return 2;
  }
  const std::string folder = argv[1];
  std::string out;
  std::vector<std::string> names = { "camel", "hand", "ChineseDragon-10kv", "mech-holes-shark",
    "fandisk", "elephant-with-holes", "armadillo" };
  std::vector<std::pair<std::string, double>> sets;
  bool ourVariants = true;
  bool timeOnly = false;
  bool withReconstruction = true; // --no-reconstruction
  std::vector<int> sizes;         // --sizes: diagonal / N on both sides
  std::string only;               // --only ours|alpha: one side
  int repeats = 1;                // --repeat: the fastest of this many runs of every wrap
  CloudSampling
    sampling; // --points (wrap that many points sampled on each mesh instead of it), --noise,
              // --draw, --ramp
  for (int a = 2; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--out" && a + 1 < argc)
    {
      out = argv[++a];
    }
    else if (arg == "--meshes" && a + 1 < argc)
    {
      names.clear();
      std::stringstream list(argv[++a]);
      for (std::string n; std::getline(list, n, ',');)
      {
        names.push_back(n);
      }
    }
    else if (arg == "--set" && a + 1 < argc)
    {
      const std::string s = argv[++a];
      const auto eq = s.find('=');
      if (eq == std::string::npos || !setters().count(s.substr(0, eq)))
      {
        std::cerr << "unknown --set " << s << "\n";
        return 2;
      }
      sets.emplace_back(s.substr(0, eq), std::stod(s.substr(eq + 1)));
    }
    else if (arg == "--points" && a + 1 < argc)
    {
      sampling.count = std::atoi(argv[++a]);
    }
    else if (arg == "--draw" && a + 1 < argc)
    {
      sampling.draw = std::max(0, std::atoi(argv[++a]));
    }
    else if (arg == "--repeat" && a + 1 < argc)
    {
      repeats = std::max(1, std::atoi(argv[++a]));
    }
    else if (arg == "--noise" && a + 1 < argc)
    {
      sampling.noise = std::stod(argv[++a]);
    }
    else if (arg == "--ramp" && a + 1 < argc)
    {
      sampling.ramp = std::max(1.0, std::stod(argv[++a]));
    }
    else if (arg == "--defaults-only")
    {
      ourVariants = false;
    }
    else if (arg == "--time-only")
    {
      ourVariants = false;
      timeOnly = true;
    }
    else if (arg == "--sizes" && a + 1 < argc)
    {
      std::stringstream list(argv[++a]);
      for (std::string n; std::getline(list, n, ',');)
      {
        sizes.push_back(std::max(1, std::atoi(n.c_str())));
      }
    }
    else if (arg == "--only" && a + 1 < argc)
    {
      only = argv[++a];
    }
    else if (arg == "--no-reconstruction")
    {
      withReconstruction = false;
    }
    else
    {
      std::cerr << "unknown argument " << arg << "\n";
      return 2;
    }
  }
  for (const std::string& name : names)
  {
    vtkSmartPointer<vtkPolyData> mesh = testing::readOFF(folder + "/" + name + ".off");
    if (!mesh)
    {
      return 1;
    }
    const TriangleSoup target = testing::triangulated(mesh);
    const double diagonal = target.bounds().diagonal();
    if (!out.empty())
    {
      write(target, out + "/" + name + "_target.vtp");
    }
    if (!timeOnly)
    {
      std::printf("\n%s: %zu triangles, distances in %% of the diagonal %.4g\n\n", name.c_str(),
        target.triangles.size(), diagonal);
      header();
    }
    if (sampling.count > 0)
    {
      cloudRows(target, sampling, sets, out.empty() ? out : out + "/" + name + "_points", !timeOnly,
        withReconstruction, repeats);
      continue;
    }

    // Ours: the defaults, then two other target edge lengths; or the --sizes; or none (--only
    // alpha).
    std::vector<double> divisors(sizes.begin(), sizes.end());
    if (sizes.empty())
    {
      divisors = ourVariants ? std::vector<double>{ 0, 25, 100 } : std::vector<double>{ 0 };
    }
    if (only == "alpha")
    {
      divisors.clear();
    }
    for (const double divisor : divisors)
    {
      vtkSmartPointer<vtkShrinkWrapFilter> wrap;
      const double total = fastestOf(repeats, [&] {
        wrap = configuredWrap(mesh, sets);
        if (divisor > 0 && !sizes.empty())
        {
          wrap->SetTargetEdgeLength(diagonal / divisor);
          wrap->SetGapSize(diagonal / divisor);
          wrap->SetResolution(static_cast<int>(std::lround(1.5 * divisor)));
        }
        else if (divisor > 0)
        {
          wrap->SetTargetEdgeLength(diagonal / divisor);
          // The field's cell follows L: the default Resolution belongs to L = diagonal / 50 (never
          // coarser).
          const int resolution = wrap->GetResolution();
          wrap->SetResolution(std::max(resolution, static_cast<int>(resolution * divisor / 50)));
        }
        wrap->Update();
      });
      vtkPolyData* result = wrap->GetOutput();
      auto* status =
        vtkStringArray::SafeDownCast(result->GetFieldData()->GetAbstractArray("Status"));
      const std::string label = divisor > 0
        ? "Shrink Wrap L = diag/" + std::to_string(static_cast<int>(divisor)) + ", Resolution " +
          std::to_string(wrap->GetResolution())
        : std::string("Shrink Wrap, defaults");
      if (timeOnly)
      {
        std::printf(
          "%s: %lld vertices, %.3f s\n", name.c_str(), result->GetNumberOfPoints(), total);
        continue;
      }
      const TriangleSoup soup = testing::triangulated(result);
      row(label, total, soup, target, status ? status->GetValue(0) : "none");
      if (!sizes.empty())
      {
        peakRow();
      }
      if (!out.empty() && divisor == 0)
      {
        write(soup, out + "/" + name + "_shrinkwrap.vtp");
      }
    }

    if (timeOnly || only == "ours")
    {
      continue;
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
      faces.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
        static_cast<std::size_t>(t[2]) });
    }
    for (const int divisor : sizes.empty() ? std::vector<int>{ 20, 50, 100 } : sizes)
    {
      const double alpha = diagonal / divisor, offset = alpha / 30;
      CgalMesh wrapped;
      const double total = fastestOf(repeats, [&] {
        wrapped.clear();
        CGAL::alpha_wrap_3(points, faces, alpha, offset, wrapped);
      });
      const TriangleSoup soup = soupOf(wrapped);
      row(kAlphaWrap + " diag/" + std::to_string(divisor), total, soup, target, "ok");
      if (!sizes.empty())
      {
        peakRow();
      }
      if (!out.empty())
      {
        write(soup, out + "/" + name + "_alphawrap_" + std::to_string(divisor) + ".vtp");
      }
    }
  }
  return 0;
}
