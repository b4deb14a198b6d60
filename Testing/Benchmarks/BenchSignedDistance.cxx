// Table 1 of the paper on this machine, with peers on the same grid in the same run.
//
//   BenchSignedDistance <mesh.obj|.off> [--runs N] [--resolutions 90,120,180,240] [--no-vtk]
//   [--no-accuracy] BenchSignedDistance <mesh> --memory R     (peak memory of one run at resolution
//   R, fresh process) BenchSignedDistance <mesh> --points N      (issue #13: N points sampled on
//   the mesh, measured as a
//                                               cloud, beside the mesh's field on the same grid)
//   BenchSignedDistance <mesh> --cube S         (issue #62's equal grid: every resolution R is a
//                                               cube of R cells a side around the bounds scaled S,
//                                               given to the filter as an explicit grid)
//
// For every resolution: Mesh Signed Distance (the filter, median of N runs, with the core's stage
// times), OpenVDB meshToVolume (narrow band of 3 voxels; and that band plus fast sweeping over the
// whole grid, by maskSdf), and VTK's vtkImplicitPolyDataDistance at every node where it finishes in
// about a minute. Accuracy (mean and max |error| in cells against exact distances from the AABB
// tree) is shown for the fields that cover the whole grid. Prints a Markdown table.
#include "Common/Parallel.h"
#include "Distance/SignedDistance.h"
#include "TestUtilities.h"
#include "WrapEvaluation.h"
#include "vtkMeshSignedDistance.h"

#include <vtkImplicitPolyDataDistance.h>
#include <vtkOBJReader.h>
#include <vtkPoints.h>

#include <openvdb/openvdb.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/MeshToVolume.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>

namespace
{
using Clock = std::chrono::steady_clock;

double seconds(const std::function<void()>& f)
{
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

vtkSmartPointer<vtkPolyData> load(const std::string& path)
{
  if (path.size() > 4 && path.substr(path.size() - 4) == ".off")
  {
    return testing::readOFF(path);
  }
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

// Mean and max |error| in cells of a field given as a function of the node, against exact
// distances.
struct Accuracy
{
  double mean = -1, max = -1;
};
Accuracy accuracyOf(const shrinkwrap::GridLattice& lattice, const std::vector<float>& exact,
  const std::function<double(int, int, int)>& value)
{
  const auto& d = lattice.dims;
  std::vector<double> sums(d[2], 0), maxes(d[2], 0);
  shrinkwrap::onAllCores([&] {
    vtkSMPTools::For(0, d[2], [&](int b, int e) {
      for (int k = b; k < e; ++k)
      {
        for (int j = 0; j < d[1]; ++j)
        {
          for (int i = 0; i < d[0]; ++i)
          {
            const double err = std::abs(std::abs(value(i, j, k)) - exact[lattice.index(i, j, k)]);
            sums[k] += err;
            maxes[k] = std::max(maxes[k], err);
          }
        }
      }
    });
  });
  const double h = lattice.minSpacing();
  double sum = 0;
  for (double s : sums)
  {
    sum += s;
  }
  return { sum / lattice.nodeCount() / h, *std::max_element(maxes.begin(), maxes.end()) / h };
}

std::vector<float> exactDistances(
  const shrinkwrap::TriangleSoup& soup, const shrinkwrap::GridLattice& lattice)
{
  const shrinkwrap::AABBTree tree(soup);
  std::vector<float> exact(lattice.nodeCount());
  const auto& d = lattice.dims;
  shrinkwrap::onAllCores([&] {
    vtkSMPTools::For(0, d[2], [&](int b, int e) {
      for (int k = b; k < e; ++k)
        for (int j = 0; j < d[1]; ++j)
          for (int i = 0; i < d[0]; ++i)
            exact[lattice.index(i, j, k)] = static_cast<float>(
              std::sqrt(tree.closestPoint(lattice.position(i, j, k)).squaredDistance));
    });
  });
  return exact;
}

struct VdbMesh
{
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
};

long currentRssKiB()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmRSS:")
    {
      long kib;
      status >> kib;
      return kib;
    }
  }
  return 0;
}
// Issue #13's speed class: the field of N points sampled on the mesh beside the mesh's own field,
// on the same grid (the mesh's), same run; its accuracy against the exact distance to the nearest
// point.
void pointRows(vtkPolyData* mesh, const shrinkwrap::TriangleSoup& soup, int count,
  const std::vector<int>& resolutions, int runs)
{
  std::vector<shrinkwrap::Vec3> cloud = testing::samplePoints(soup, count, 7);
  cloud.erase(
    cloud.begin(), cloud.begin() + static_cast<std::ptrdiff_t>(soup.points.size())); // samples only
  vtkNew<vtkPoints> points;
  for (const shrinkwrap::Vec3& p : cloud)
    points->InsertNextPoint(p.data());
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  std::printf("%d points sampled on the mesh, %d runs per figure (median)\n\n", count, runs);
  std::printf("| grid | nodes | mesh field | **points field** | ratio points / mesh | points mean "
              "err | points max err |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (int resolution : resolutions)
  {
    vtkNew<vtkMeshSignedDistance> meshField, pointField;
    meshField->SetInputData(mesh);
    meshField->SetResolution(resolution);
    meshField->SetOffsetFactor(shrinkwrap::kPaperOffsetFactor);
    meshField->Update();
    const shrinkwrap::GridLattice lattice = testing::latticeOf(meshField->GetOutput());
    pointField->SetInputData(input);
    pointField->UseExplicitGridOn();
    const shrinkwrap::Box box = lattice.bounds();
    pointField->SetOutputBounds(
      box.min.x(), box.max.x(), box.min.y(), box.max.y(), box.min.z(), box.max.z());
    pointField->SetOutputDimensions(lattice.dims[0], lattice.dims[1], lattice.dims[2]);
    std::vector<double> meshTimes, pointTimes; // interleaved: the machine's noise hits both
    for (int r = 0; r < runs; ++r)
    {
      meshField->Modified();
      meshTimes.push_back(seconds([&] { meshField->Update(); }));
      pointField->Modified();
      pointTimes.push_back(seconds([&] { pointField->Update(); }));
    }
    shrinkwrap::TriangleSoup pointSoup; // one triangle {i, i, i} per point: the exact nearest point
    pointSoup.points = cloud;
    for (int i = 0; i < static_cast<int>(cloud.size()); ++i)
      pointSoup.triangles.push_back({ i, i, i });
    const std::vector<float> exact = exactDistances(pointSoup, lattice);
    auto* values = vtkFloatArray::SafeDownCast(
      pointField->GetOutput()->GetPointData()->GetArray("SignedDistance"));
    const Accuracy accuracy = accuracyOf(lattice, exact,
      [&](int i, int j, int k) { return values->GetValue(lattice.index(i, j, k)); });
    std::printf("| %dx%dx%d | %lld | %.3f | **%.3f** | %.2f | %.3f h | %.3f h |\n",
      lattice.dims[0] - 1, lattice.dims[1] - 1, lattice.dims[2] - 1,
      static_cast<long long>(lattice.nodeCount()), median(meshTimes), median(pointTimes),
      median(pointTimes) / median(meshTimes), accuracy.mean, accuracy.max);
  }
}
// The cube of `resolution` cells a side around the mesh's bounds scaled by `scale` about their
// centre, as the filter's explicit grid.
void useCube(vtkMeshSignedDistance* filter, vtkPolyData* mesh, double scale, int resolution)
{
  double b[6];
  mesh->GetBounds(b);
  const double half = scale * std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] }) / 2;
  double bounds[6];
  for (int a = 0; a < 3; ++a)
  {
    const double centre = (b[2 * a] + b[2 * a + 1]) / 2;
    bounds[2 * a] = centre - half;
    bounds[2 * a + 1] = centre + half;
  }
  filter->UseExplicitGridOn();
  filter->SetOutputBounds(bounds);
  filter->SetOutputDimensions(resolution + 1, resolution + 1, resolution + 1);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: BenchSignedDistance mesh [--runs N] [--resolutions a,b] [--no-vtk] "
                 "[--no-accuracy] [--memory R] "
                 "[--points N]\n";
    return 2;
  }
  int runs = 5, memoryResolution = 0, pointCount = 0;
  double cubeScale = 0;
  bool runVtk = true, runAccuracy = true;
  std::vector<int> resolutions = { 90, 120, 180, 240 };
  for (int a = 2; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--runs" && a + 1 < argc)
      runs = std::atoi(argv[++a]);
    else if (arg == "--resolutions" && a + 1 < argc)
    {
      resolutions.clear();
      std::stringstream list(argv[++a]);
      std::string item;
      while (std::getline(list, item, ','))
        resolutions.push_back(std::stoi(item));
    }
    else if (arg == "--no-vtk")
      runVtk = false;
    else if (arg == "--no-accuracy")
      runAccuracy = false;
    else if (arg == "--memory" && a + 1 < argc)
      memoryResolution = std::atoi(argv[++a]);
    else if (arg == "--points" && a + 1 < argc)
      pointCount = std::atoi(argv[++a]);
    else if (arg == "--cube" && a + 1 < argc)
      cubeScale = std::atof(argv[++a]);
  }

  vtkSmartPointer<vtkPolyData> mesh = load(argv[1]);
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  const shrinkwrap::TriangleSoup soup = testing::triangulated(mesh);

  if (pointCount > 0)
  {
    pointRows(mesh, soup, pointCount, resolutions, runs);
    return 0;
  }
  if (memoryResolution > 0)
  {
    const long before = currentRssKiB();
    vtkNew<vtkMeshSignedDistance> filter;
    filter->SetInputData(mesh);
    filter->SetResolution(memoryResolution);
    if (cubeScale > 0)
      useCube(filter, mesh, cubeScale, memoryResolution);
    filter->Update();
    const double output = 4.0 * filter->GetOutput()->GetNumberOfPoints() / 1024;
    const long peak = testing::peakRssKiB();
    std::printf("memory at resolution %d: output array %.1f MiB, peak RSS growth %.1f MiB = %.2f x "
                "the output "
                "array (mesh and process before the run: %.1f MiB)\n",
      memoryResolution, output / 1024, (peak - before) / 1024.0, (peak - before) / output,
      before / 1024.0);
    return 0;
  }

  openvdb::initialize();
  VdbMesh vdbMesh;
  for (const auto& p : soup.points)
    vdbMesh.points.emplace_back(p.x(), p.y(), p.z());
  for (const auto& t : soup.triangles)
    vdbMesh.triangles.emplace_back(t[0], t[1], t[2]);

  vtkNew<vtkImplicitPolyDataDistance> vtkDistance;
  vtkDistance->SetInput(mesh);

  std::printf("mesh %s: %zu triangles, %d runs per figure (median), %d threads\n\n", argv[1],
    soup.triangles.size(), runs,
    std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
  std::printf(
    "| grid | nodes | tree | outline | band | sweep | sign | **ours total** | mean err | max err "
    "| VDB band 3 | VDB band+sweep | VDB mean err | VDB max err | ratio VDB b+s / ours | "
    "vtkImplicitPolyDataDistance | ratio VTK / ours "
    "| signed by | core | core without winding number | ratio | sampled far nodes against the "
    "winding number |\n");
  std::printf(
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  double vtkSecondsPerNode = 0;
  for (int resolution : resolutions)
  {
    vtkNew<vtkMeshSignedDistance> filter;
    filter->SetInputData(mesh);
    filter->SetResolution(resolution);
    filter->SetOffsetFactor(shrinkwrap::kPaperOffsetFactor); // Table 1's grid: the paper's box
    if (cubeScale > 0)
      useCube(filter, mesh, cubeScale, resolution);
    std::vector<double> totals;
    for (int r = 0; r < runs; ++r)
    {
      filter->Modified();
      totals.push_back(seconds([&] { filter->Update(); }));
    }
    vtkImageData* image = filter->GetOutput();
    const shrinkwrap::GridLattice lattice = testing::latticeOf(image);

    // Stage times from the core on the same grid, and the core's time without the winding-number
    // sign (where the votes disagree the field then stays unsigned, as before issue #11),
    // interleaved.
    std::vector<shrinkwrap::SignedDistanceResult> stages;
    std::vector<float> scratch(lattice.nodeCount());
    std::vector<double> core, votesOnly;
    shrinkwrap::SignedDistanceSettings withoutWinding;
    withoutWinding.windingNumber = false;
    for (int r = 0; r < runs; ++r)
    {
      shrinkwrap::onAllCores([&] {
        core.push_back(seconds([&] {
          stages.push_back(shrinkwrap::computeSignedDistance(soup, lattice, {}, scratch.data()));
        }));
        votesOnly.push_back(seconds([&] {
          shrinkwrap::computeSignedDistance(soup, lattice, withoutWinding, scratch.data());
        }));
      });
    }
    const shrinkwrap::SignedDistanceResult& last = stages.back();
    const char* signedBy = !last.isSigned
      ? "unsigned"
      : (last.signMethod == shrinkwrap::SignMethod::WindingNumber ? "winding number" : "votes");
    auto stage = [&](double shrinkwrap::SignedDistanceResult::*field) {
      std::vector<double> v;
      for (const auto& s : stages)
        v.push_back(s.*field);
      return median(v);
    };

    // OpenVDB on the same lattice: voxel size h, index space = our node indices.
    const double h = lattice.spacing[0];
    auto transform = openvdb::math::Transform::createLinearTransform(h);
    transform->postTranslate(
      openvdb::Vec3d(lattice.origin.x(), lattice.origin.y(), lattice.origin.z()));
    std::vector<openvdb::Vec3s> indexPoints;
    for (const auto& p : vdbMesh.points)
      indexPoints.push_back(transform->worldToIndex(p));
    std::vector<double> band, full;
    openvdb::FloatGrid::Ptr vdbFull;
    for (int r = 0; r < runs; ++r)
    {
      openvdb::FloatGrid::Ptr narrow;
      band.push_back(seconds([&] {
        narrow = openvdb::tools::meshToSignedDistanceField<openvdb::FloatGrid>(
          *transform, vdbMesh.points, vdbMesh.triangles, {}, 3.0f, 3.0f);
      }));
      full.push_back(band.back() + seconds([&] {
        openvdb::BoolGrid mask(false);
        mask.setTransform(transform);
        mask.denseFill(
          openvdb::CoordBBox(openvdb::Coord(0),
            openvdb::Coord(lattice.dims[0] - 1, lattice.dims[1] - 1, lattice.dims[2] - 1)),
          true, true);
        vdbFull = openvdb::tools::maskSdf(*narrow, mask);
      }));
    }

    Accuracy ours, vdb;
    if (runAccuracy)
    {
      const std::vector<float> exact = exactDistances(soup, lattice);
      auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
      ours = accuracyOf(lattice, exact,
        [&](int i, int j, int k) { return values->GetValue(lattice.index(i, j, k)); });
      vdb = accuracyOf(lattice, exact, [&](int i, int j, int k) {
        return vdbFull->tree().getValue(
          openvdb::Coord(i, j, k)); // thread-safe read without accessor caching
      });
    }

    // vtkImplicitPolyDataDistance at every node, where about a minute suffices.
    std::string vtkCell = "-", vtkRatio = "-";
    if (runVtk)
    {
      if (vtkSecondsPerNode == 0)
      {
        // Calibrate on a slice of nodes.
        const int sample = 20000;
        vtkSecondsPerNode = seconds([&] {
          for (int n = 0; n < sample; ++n)
          {
            const shrinkwrap::Vec3 x = lattice.position(
              n % lattice.dims[0], (n / lattice.dims[0]) % lattice.dims[1], lattice.dims[2] / 2);
            vtkDistance->EvaluateFunction(const_cast<double*>(x.data()));
          }
        }) /
          sample;
      }
      if (vtkSecondsPerNode * lattice.nodeCount() < 60)
      {
        const double t = seconds([&] {
          for (int k = 0; k < lattice.dims[2]; ++k)
            for (int j = 0; j < lattice.dims[1]; ++j)
              for (int i = 0; i < lattice.dims[0]; ++i)
                vtkDistance->EvaluateFunction(
                  const_cast<double*>(lattice.position(i, j, k).data()));
        });
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.2f s", t);
        vtkCell = buffer;
        std::snprintf(buffer, sizeof buffer, "%.0f", t / median(totals));
        vtkRatio = buffer;
      }
      else
      {
        char buffer[64];
        std::snprintf(
          buffer, sizeof buffer, "(~%.0f s, skipped)", vtkSecondsPerNode * lattice.nodeCount());
        vtkCell = buffer;
      }
    }

    // The sign against the brute-force winding number on a sample of nodes farther than a cell.
    const testing::SignSample signs = testing::sampleSigns(image, soup, 4000);
    std::printf(
      "| %dx%dx%d | %lld | %.3f | %.3f | %.3f | %.3f | %.3f | **%.3f** | %.3f h | %.3f h | %.3f | "
      "%.3f | %.3f h | %.3f h | %.1f | %s | %s | %s | %.3f | %.3f | %.2f | %lld of %lld |\n",
      lattice.dims[0] - 1, lattice.dims[1] - 1, lattice.dims[2] - 1,
      static_cast<long long>(lattice.nodeCount()),
      stage(&shrinkwrap::SignedDistanceResult::treeSeconds),
      stage(&shrinkwrap::SignedDistanceResult::outlineSeconds),
      stage(&shrinkwrap::SignedDistanceResult::bandSeconds),
      stage(&shrinkwrap::SignedDistanceResult::sweepSeconds),
      stage(&shrinkwrap::SignedDistanceResult::signSeconds), median(totals), ours.mean, ours.max,
      median(band), median(full), vdb.mean, vdb.max, median(full) / median(totals), vtkCell.c_str(),
      vtkRatio.c_str(), signedBy, median(core), median(votesOnly), median(core) / median(votesOnly),
      signs.disagreeing, signs.far);
    std::fflush(stdout);
  }
  return 0;
}
