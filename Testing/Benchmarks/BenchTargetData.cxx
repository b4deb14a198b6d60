// The target's data on the wrap and the target measured (issue #64), on the benchmark's meshes at
// the defaults:
//   BenchTargetData <CGAL data/meshes folder> [--meshes a,b,...] [--repeat N] [--points N]
// Each mesh gets a point array p (x^2 + 3y over the box, two components more) and a cell array (an
// id per octant). Time: a default wrap with Pass Target Arrays on and off, each by a new filter,
// alternating, the fastest of N each, and their ratio; then, on the finished wrap, what each part
// of the measuring costs (the cells of the target's triangles, read through the session's distance
// source, or with a tree of its own; passing the arrays; the target measured with the wrap's
// distance source; the sampled distances of the summary), as the filter runs them. Closeness: the
// largest |DistanceToWrap| against the benchmark's sampled largest distance target -> wrap
// (WrapEvaluation.h, 100,000 points plus the vertices; BENCH_SAMPLES=N in the environment samples
// N), and the target measured's field LargestDistanceToWrap (over its whole surface).
// --points N wraps N points sampled on each mesh instead, with p at the points (the
// wrap's times alone).
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkShrinkWrapFilter.h"

#include "TargetData.h"

#include "Common/Parallel.h"
#include "Distance/DistanceSource.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <sstream>

namespace
{
using shrinkwrap::Vec3;

double seconds(const std::chrono::steady_clock::time_point& begin)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// p (3 components: x^2 + 3y and two more) at the points, an octant id per cell.
void addData(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  vtkNew<vtkDoubleArray> p;
  p->SetName("p");
  p->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    const double u = (x[0] - b[0]) / (b[1] - b[0]), v = (x[1] - b[2]) / (b[3] - b[2]);
    p->InsertNextTuple3(u * u + 3 * v, u, v);
  }
  mesh->GetPointData()->AddArray(p);
  vtkNew<vtkIntArray> octant;
  octant->SetName("octant");
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    double x[3] = { 0, 0, 0 };
    if (ids->GetNumberOfIds() > 0)
    {
      mesh->GetPoint(ids->GetId(0), x);
    }
    int id = 0;
    for (int a = 0; a < 3; ++a)
    {
      id |= (x[a] > 0.5 * (b[2 * a] + b[2 * a + 1])) << a;
    }
    octant->InsertNextValue(id);
  }
  mesh->GetCellData()->AddArray(octant);
}

vtkSmartPointer<vtkPolyData> sampledCloud(vtkPolyData* mesh, int count)
{
  const shrinkwrap::TriangleSoup soup = testing::triangulated(mesh);
  std::vector<Vec3> points = shrinkwrap::samplePoints(soup, count, 7);
  points.erase(points.begin(), points.begin() + soup.points.size()); // the random ones alone
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> xyz;
  vtkNew<vtkCellArray> vertices;
  for (const Vec3& x : points)
  {
    vertices->InsertNextCell(1);
    vertices->InsertCellPoint(xyz->InsertNextPoint(x.data()));
  }
  cloud->SetPoints(xyz);
  cloud->SetVerts(vertices);
  return cloud;
}

double largestAbs(vtkDataArray* a)
{
  double largest = 0;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    largest = std::max(largest, std::abs(a->GetTuple1(i)));
  }
  return largest;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BenchTargetData <CGAL data/meshes folder> [--meshes a,b] [--repeat N] "
                 "[--points N]\n";
    return 1;
  }
  const std::string folder = argv[1];
  std::vector<std::string> names = { "camel", "hand", "ChineseDragon-10kv", "mech-holes-shark",
    "fandisk", "elephant-with-holes", "armadillo" };
  int repeats = 3, points = 0;
  for (int a = 2; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--meshes" && a + 1 < argc)
    {
      names.clear();
      std::stringstream list(argv[++a]);
      for (std::string name; std::getline(list, name, ',');)
      {
        names.push_back(name);
      }
    }
    else if (arg == "--repeat" && a + 1 < argc)
    {
      repeats = std::max(1, std::atoi(argv[++a]));
    }
    else if (arg == "--points" && a + 1 < argc)
    {
      points = std::atoi(argv[++a]);
    }
  }
  std::cout << "| target | vertices | wrap, arrays off (s) | arrays on (s) | on / off | cells (s) "
               "| cells and own tree (s) | passing (s) | target measured (s) | sampled summary (s) "
               "| largest abs "
               "DistanceToWrap | LargestDistanceToWrap | sampled target to wrap largest | ratio "
               "(array) | ratio (field) |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& name : names)
  {
    vtkSmartPointer<vtkPolyData> mesh = testing::readOFF(folder + "/" + name + ".off");
    if (!mesh || mesh->GetNumberOfPoints() == 0)
    {
      std::cerr << "cannot read " << name << "\n";
      continue;
    }
    vtkSmartPointer<vtkPolyData> target = points > 0 ? sampledCloud(mesh, points) : mesh;
    addData(target);
    double off = 1e30, on = 1e30;
    vtkSmartPointer<vtkShrinkWrapFilter> last;
    for (int r = 0; r < repeats; ++r)
    {
      for (bool pass : { false, true })
      {
        auto wrap = vtkSmartPointer<vtkShrinkWrapFilter>::New();
        wrap->SetInputData(target);
        wrap->SetPassTargetArrays(pass);
        const auto begin = std::chrono::steady_clock::now();
        wrap->UpdateTimeStep(1e30);
        (pass ? on : off) = std::min(pass ? on : off, seconds(begin));
        last = wrap;
      }
    }
    auto* surface = vtkPolyData::SafeDownCast(last->GetOutputDataObject(0));
    auto* measured = vtkPolyData::SafeDownCast(last->GetOutputDataObject(1));
    // The measuring's parts again on the finished wrap, as the filter runs them.
    const shrinkwrap::TriangleSoup wrapSoup = testing::triangulated(surface);
    double building = 1e30, owning = 1e30, passing = 1e30, measuring = 1e30, sampling = 1e30;
    vtkDataArray* gap = surface->GetFieldData()->GetArray("GapSize");
    for (int r = 0; points == 0 && r < repeats; ++r)
    {
      shrinkwrap::onAllCores([&] {
        // The carrier as the filter makes it: through the session's distance source (built for
        // the wrap: not timed here), the cells alone; and with a tree of its own.
        shrinkwrap::convert::SoupCounts counts;
        auto soup = std::make_shared<const shrinkwrap::TriangleSoup>(
          shrinkwrap::convert::soupOf({ target.Get() }, counts));
        auto session = std::make_shared<const shrinkwrap::TriangleSource>(*soup);
        auto begin = std::chrono::steady_clock::now();
        auto carrier = shrinkwrap::convert::makeCarrier(target, soup, session);
        building = std::min(building, seconds(begin));
        begin = std::chrono::steady_clock::now();
        auto own = shrinkwrap::convert::makeCarrier(target, soup, nullptr);
        owning = std::min(owning, seconds(begin));
        begin = std::chrono::steady_clock::now();
        vtkNew<vtkPolyData> copy;
        copy->ShallowCopy(surface);
        std::vector<std::string> renamed;
        shrinkwrap::convert::passTargetArrays(target, carrier.get(), nullptr, copy, renamed);
        passing = std::min(passing, seconds(begin));
        begin = std::chrono::steady_clock::now();
        const shrinkwrap::TriangleSource source(wrapSoup);
        const double wrapSource = seconds(begin);
        begin = std::chrono::steady_clock::now();
        shrinkwrap::convert::measureTarget(target, source, gap ? gap->GetTuple1(0) : 0.0, true);
        measuring = std::min(measuring, seconds(begin) + wrapSource);
        begin = std::chrono::steady_clock::now();
        shrinkwrap::measureCloseness(
          wrapSoup, source,
          [&](const Vec3& p) {
            return session->closestPoint(p, std::numeric_limits<double>::infinity())
              .squaredDistance;
          },
          soup.get(), nullptr, shrinkwrap::convert::kSummarySamples);
        sampling = std::min(sampling, seconds(begin));
      });
    }
    const double diagonal = testing::triangulated(mesh).bounds().diagonal();
    const double largest =
      largestAbs(measured ? measured->GetPointData()->GetArray("DistanceToWrap") : nullptr);
    vtkDataArray* farthest =
      measured ? measured->GetFieldData()->GetArray("LargestDistanceToWrap") : nullptr;
    const double field = farthest ? farthest->GetTuple1(0) : 0.0;
    double sampled = 0;
    if (points == 0)
    {
      const char* many = std::getenv("BENCH_SAMPLES"); // more than the benchmark's 100,000
      sampled = testing::evaluateWrap(
                  wrapSoup, testing::triangulated(mesh), many ? std::atoi(many) : 100000)
                  .targetToWrap.largest *
        diagonal / 100;
    }
    std::printf(
      "| %s%s | %lld | %.3f | %.3f | %.3f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4g | %.4g | %.4g "
      "| %.3f | %.3f |\n",
      name.c_str(), points > 0 ? " (points)" : "",
      static_cast<long long>(surface->GetNumberOfPoints()), off, on, on / off, building, owning,
      passing, measuring, sampling, largest, field, sampled, sampled > 0 ? largest / sampled : 0.0,
      sampled > 0 ? field / sampled : 0.0);
    std::fflush(stdout);
  }
  return 0;
}
