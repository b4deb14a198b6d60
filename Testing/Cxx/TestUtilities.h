// Helpers shared by the C++ tests: mesh loading, independent reference fields, checks.
#ifndef ShrinkWrap_TestUtilities_h
#define ShrinkWrap_TestUtilities_h

#include "Common/TriangleSoup.h"
#include "Distance/AABBTree.h"
#include "Distance/GridLattice.h"
#include "Distance/TriangleDistance.h"
#include "Distance/WindingNumber.h"
#include "Surface/SurfaceMesh.h"
#include "VTKConversions.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <sys/resource.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <mutex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace testing
{
using shrinkwrap::Vec3;

// The process's peak resident memory so far, in KiB (benchmarks).
inline long peakRssKiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

inline int& failures()
{
  static int count = 0;
  return count;
}

#define SW_CHECK(condition, message)                                                               \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << "FAILED: " << message << "  [" #condition "] at " __FILE__ ":" << __LINE__      \
                << std::endl;                                                                      \
      ++testing::failures();                                                                       \
    }                                                                                              \
  } while (false)

// n points on a unit sphere (uniform directions), each then moved by Gaussian noise of sigma.
inline std::vector<Vec3> spherePoints(int n, double sigma, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> points(n);
  for (Vec3& p : points)
  {
    p = Vec3(g(rng), g(rng), g(rng)).normalized();
    p += sigma * Vec3(g(rng), g(rng), g(rng));
  }
  return points;
}

inline int finish(const char* name)
{
  std::cout << name << ": " << (failures() ? "FAILED" : "passed") << " (" << failures()
            << " failed checks)" << std::endl;
  return failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}

// SurfaceMesh::build with the reason in `error` (empty when it builds).
inline bool builds(const std::vector<Vec3>& points,
  const std::vector<std::array<int, 3>>& triangles, shrinkwrap::SurfaceMesh& mesh,
  std::string& error)
{
  const shrinkwrap::Status status = shrinkwrap::SurfaceMesh::build(points, triangles, mesh);
  error = status.message();
  return status.ok();
}

// A closed surface's mesh; a failed check if it is not one.
inline shrinkwrap::SurfaceMesh meshOf(const shrinkwrap::TriangleSoup& surface)
{
  shrinkwrap::SurfaceMesh mesh;
  std::string error;
  SW_CHECK(builds(surface.points, surface.triangles, mesh, error), "surface builds: " << error);
  return mesh;
}

// The cell of the distance field a Shrink Wrap output moved on (its field data FieldCellSize); 0 if
// the output has none.
inline double fieldCell(vtkDataObject* wrap)
{
  vtkDataArray* cell = wrap->GetFieldData()->GetArray("FieldCellSize");
  return cell && cell->GetNumberOfTuples() > 0 ? cell->GetTuple1(0) : 0.0;
}

// A mesh in OFF format (CGAL's data set) as vtkPolyData with its polygons as they are.
inline vtkSmartPointer<vtkPolyData> readOFF(const std::string& path)
{
  std::ifstream in(path);
  std::string header;
  in >> header;
  if (!in || header.find("OFF") == std::string::npos)
  {
    std::cerr << "cannot read OFF file " << path << std::endl;
    return nullptr;
  }
  long long nv, nf, ne;
  in >> nv >> nf >> ne;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (long long i = 0; i < nv; ++i)
  {
    double p[3];
    in >> p[0] >> p[1] >> p[2];
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  for (long long f = 0; f < nf; ++f)
  {
    int n;
    in >> n;
    std::vector<vtkIdType> ids(n);
    for (auto& id : ids)
    {
      in >> id;
    }
    std::string rest;
    std::getline(in, rest); // optional colour
    polys->InsertNextCell(n, ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return in ? mesh : nullptr;
}

// Triangles of a mesh by VTK's own triangulation: the reference does not share the filter's code.
inline shrinkwrap::TriangleSoup triangulated(vtkPolyData* mesh)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(mesh);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  shrinkwrap::TriangleSoup soup;
  shrinkwrap::convert::surfaceOf(triangles->GetOutput(), soup);
  return soup;
}

// Exact distance by looking at every triangle.
inline double bruteForceDistance(const shrinkwrap::TriangleSoup& soup, const Vec3& x)
{
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : soup.triangles)
  {
    const auto hit = shrinkwrap::closestPointOnTriangle(
      x, soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
    best = std::min(best, (hit.point - x).squaredNorm());
  }
  return std::sqrt(best);
}

inline shrinkwrap::GridLattice latticeOf(vtkImageData* image)
{
  shrinkwrap::GridLattice lattice;
  image->GetOrigin(lattice.origin.data());
  image->GetSpacing(lattice.spacing.data());
  image->GetDimensions(lattice.dims.data());
  return lattice;
}

// Winding number at every node by casting a ray up +z from each grid column and adding +1 or -1 at
// every crossing above the node, by the side the triangle faces. For a closed mesh it is the
// generalised winding number; nonzero means inside. Columns are shifted by a tiny irrational amount
// so that rays miss edges and vertices.
inline std::vector<int> windingNumbers(
  const shrinkwrap::TriangleSoup& soup, const shrinkwrap::GridLattice& lattice)
{
  const auto& d = lattice.dims;
  const double dx = 1.234567e-7 * lattice.spacing[0], dy = 2.718281e-7 * lattice.spacing[1];
  std::vector<std::vector<std::pair<double, int>>> columns(static_cast<std::size_t>(d[0]) * d[1]);
  for (const auto& t : soup.triangles)
  {
    const Vec3 &a = soup.points[t[0]], &b = soup.points[t[1]], &c = soup.points[t[2]];
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    if (area2 == 0)
    {
      continue;
    }
    const int i0 = std::max(0,
      static_cast<int>(std::floor(
        (std::min({ a.x(), b.x(), c.x() }) - dx - lattice.origin.x()) / lattice.spacing.x())));
    const int i1 = std::min(d[0] - 1,
      static_cast<int>(std::ceil(
        (std::max({ a.x(), b.x(), c.x() }) - dx - lattice.origin.x()) / lattice.spacing.x())));
    const int j0 = std::max(0,
      static_cast<int>(std::floor(
        (std::min({ a.y(), b.y(), c.y() }) - dy - lattice.origin.y()) / lattice.spacing.y())));
    const int j1 = std::min(d[1] - 1,
      static_cast<int>(std::ceil(
        (std::max({ a.y(), b.y(), c.y() }) - dy - lattice.origin.y()) / lattice.spacing.y())));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const double px = lattice.origin.x() + i * lattice.spacing.x() + dx;
        const double py = lattice.origin.y() + j * lattice.spacing.y() + dy;
        // Barycentric coordinates of the column in the projected triangle.
        const double w0 = ((b.x() - px) * (c.y() - py) - (c.x() - px) * (b.y() - py)) / area2;
        const double w1 = ((c.x() - px) * (a.y() - py) - (a.x() - px) * (c.y() - py)) / area2;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0)
        {
          continue;
        }
        const double z = w0 * a.z() + w1 * b.z() + w2 * c.z();
        columns[i + static_cast<std::size_t>(d[0]) * j].push_back({ z, area2 > 0 ? 1 : -1 });
      }
    }
  }
  std::vector<int> winding(lattice.nodeCount(), 0);
  for (int j = 0; j < d[1]; ++j)
  {
    for (int i = 0; i < d[0]; ++i)
    {
      for (const auto& crossing : columns[i + static_cast<std::size_t>(d[0]) * j])
      {
        for (int k = 0; k < d[2] && lattice.origin.z() + k * lattice.spacing.z() < crossing.first;
             ++k)
        {
          winding[lattice.index(i, j, k)] += crossing.second;
        }
      }
    }
  }
  return winding;
}

struct SignSample
{
  long long far = 0; // sampled nodes farther than a cell from the surface
  long long disagreeing =
    0; // of those, on the other side of the brute-force winding number (|w| > 1/2)
};

// The sign of `samples` random nodes (a fixed seed) against the generalized winding number summed
// over every triangle.
inline SignSample sampleSigns(
  vtkImageData* image, const shrinkwrap::TriangleSoup& soup, int samples)
{
  const shrinkwrap::GridLattice lattice = latticeOf(image);
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  SignSample result;
  if (!values)
  {
    result.disagreeing = result.far = 1;
    return result;
  }
  const shrinkwrap::WindingNumber winding(soup);
  std::mt19937_64 random(11);
  std::vector<std::int64_t> nodes;
  for (int s = 0; s < samples; ++s)
  {
    const std::int64_t n =
      static_cast<std::int64_t>(random() % static_cast<std::uint64_t>(lattice.nodeCount()));
    if (std::abs(values->GetValue(n)) > lattice.minSpacing())
    {
      nodes.push_back(n);
    }
  }
  std::atomic<long long> disagreeing{ 0 };
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [&] {
    vtkSMPTools::For(0, static_cast<vtkIdType>(nodes.size()), [&](vtkIdType b, vtkIdType e) {
      for (vtkIdType s = b; s < e; ++s)
      {
        const double w = winding.exactAt(lattice.position(lattice.coordinates(nodes[s])));
        disagreeing += (values->GetValue(nodes[s]) < 0) != (std::abs(w) > 0.5);
      }
    });
  });
  result.far = static_cast<long long>(nodes.size());
  result.disagreeing = disagreeing;
  return result;
}

struct FieldErrors
{
  double meanError = 0; // over every node, in cells
  double maxError = 0;  // in cells
  double bandMaxError =
    0; // over nodes within 0.5 h of the surface, as a fraction of the box diagonal
  long long signErrors = 0; // nodes farther than 0.5 h whose sign differs from the winding number
  long long nodes = 0;
};

// Compares a SignedDistance image with exact distances (the AABB tree, or every triangle when
// brute) and with winding numbers; signed = false compares magnitudes only.
inline FieldErrors compareWithReference(
  vtkImageData* image, const shrinkwrap::TriangleSoup& soup, bool brute, bool checkSign)
{
  const shrinkwrap::GridLattice lattice = latticeOf(image);
  auto* values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("SignedDistance"));
  FieldErrors errors;
  if (!values || values->GetNumberOfValues() != lattice.nodeCount())
  {
    errors.maxError = errors.meanError = std::numeric_limits<double>::infinity();
    return errors;
  }
  const shrinkwrap::AABBTree tree(soup);
  const std::vector<int> winding = checkSign ? windingNumbers(soup, lattice) : std::vector<int>();
  const double h = lattice.minSpacing();
  const double diagonal = soup.bounds().diagonal();
  std::mutex mutex;
  const auto& d = lattice.dims;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [&] {
    vtkSMPTools::For(0, static_cast<long long>(d[1]) * d[2], [&](long long b, long long e) {
      double sum = 0, worst = 0, band = 0;
      long long signs = 0;
      for (long long row = b; row < e; ++row)
      {
        const int j = static_cast<int>(row % d[1]), k = static_cast<int>(row / d[1]);
        for (int i = 0; i < d[0]; ++i)
        {
          const Vec3 x = lattice.position(i, j, k);
          const double exact =
            brute ? bruteForceDistance(soup, x) : std::sqrt(tree.closestPoint(x).squaredDistance);
          const double value = values->GetValue(lattice.index(i, j, k));
          const double error = std::abs(std::abs(value) - exact);
          sum += error;
          worst = std::max(worst, error);
          if (exact <= 0.5 * h)
          {
            band = std::max(band, error);
          }
          else if (checkSign && ((value < 0) != (winding[lattice.index(i, j, k)] != 0)))
          {
            ++signs;
          }
        }
      }
      std::lock_guard<std::mutex> lock(mutex);
      errors.meanError += sum;
      errors.maxError = std::max(errors.maxError, worst);
      errors.bandMaxError = std::max(errors.bandMaxError, band);
      errors.signErrors += signs;
    });
  });
  errors.nodes = lattice.nodeCount();
  errors.meanError /= errors.nodes * h;
  errors.maxError /= h;
  errors.bandMaxError /= diagonal;
  return errors;
}

inline void printErrors(const std::string& name, const FieldErrors& e)
{
  std::printf("%-28s nodes %9lld  mean %.4f h  max %.4f h  band max %.2e diag  sign errors %lld\n",
    name.c_str(), e.nodes, e.meanError, e.maxError, e.bandMaxError, e.signErrors);
}

// The bars of issue #2 on accuracy.
inline void checkAccuracy(const std::string& name, const FieldErrors& e, bool checkSign)
{
  printErrors(name, e);
  SW_CHECK(e.bandMaxError <= 1e-5, name << ": band nodes exact to 1e-5 of the diagonal");
  SW_CHECK(e.meanError <= 0.1, name << ": mean |error| <= 0.1 h");
  SW_CHECK(e.maxError <= 1.0, name << ": max |error| <= 1.0 h");
  if (checkSign)
  {
    SW_CHECK(e.signErrors == 0, name << ": no sign errors farther than 0.5 h from the surface");
  }
}

} // namespace testing

#endif
