// Algorithm 1 in the core, without a pipeline: the outline holds every cell a triangle touches, the
// band's distances are exact, both far-field sweeps stay near the exact distance (the closest-point
// passes never below it), and the sign votes give inside and outside of a closed mesh; one with a
// hole wider than the band (a narrower one is sealed by it) is signed by the winding number
// instead.
#include "Distance/DistanceBand.h"
#include "Distance/Outline.h"
#include "Distance/SignedDistance.h"
#include "Distance/TriangleBoxOverlap.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <set>

namespace
{
using namespace shrinkwrap;

struct Setup
{
  TriangleSoup soup = icosphere(3, Vec3(0.05, -0.03, 0.02), 1.0);
  GridLattice lattice;
  Setup() { placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.5, 24, 0 }, lattice); }
  double h() const { return this->lattice.spacing.x(); }
};

void outline()
{
  const Setup s;
  IndexList cells;
  SW_CHECK(outlineCells(s.soup, s.lattice, {}, cells), "the outline completes");
  std::set<std::int64_t> found(cells.begin(), cells.end());
  // Brute force: every cell box against every triangle.
  long long missing = 0, extra = 0;
  for (int k = 0; k + 1 < s.lattice.dims[2]; ++k)
    for (int j = 0; j + 1 < s.lattice.dims[1]; ++j)
      for (int i = 0; i + 1 < s.lattice.dims[0]; ++i)
      {
        Box cell;
        cell.extend(s.lattice.position(i, j, k));
        cell.extend(s.lattice.position(i + 1, j + 1, k + 1));
        bool touched = false;
        for (const auto& t : s.soup.triangles)
        {
          touched = touched ||
            triangleOverlapsBox(
              s.soup.points[t[0]], s.soup.points[t[1]], s.soup.points[t[2]], cell);
        }
        const bool listed = found.count(s.lattice.index(i, j, k)) > 0;
        missing += touched && !listed;
        extra += listed && !touched;
      }
  std::printf("outline: %zu cells, %lld missing, %lld extra against brute force\n", found.size(),
    missing, extra);
  SW_CHECK(
    missing == 0 && extra == 0, "the octree outline is exactly the cells the surface touches");
}

void fieldAgainstExact(SweepMethod sweep, double meanBound, double maxBound)
{
  const Setup s;
  SignedDistanceSettings settings;
  settings.sweep = sweep;
  std::vector<float> d(s.lattice.nodeCount());
  const SignedDistanceResult r = computeSignedDistance(s.soup, s.lattice, settings, d.data());
  SW_CHECK(
    r.completed && r.isSigned && !r.invertedOrientation, "a closed sphere's field is signed");
  double sum = 0, worst = 0, worstBand = 0, below = 0;
  long long signErrors = 0;
  for (std::int64_t n = 0; n < s.lattice.nodeCount(); ++n)
  {
    const Vec3 x = s.lattice.position(s.lattice.coordinates(n));
    const double exact = testing::bruteForceDistance(s.soup, x);
    const double error = std::abs(std::abs(d[n]) - exact);
    sum += error;
    worst = std::max(worst, error);
    below = std::max(below, exact - std::abs(d[n]));
    if (exact < s.h())
    {
      worstBand = std::max(worstBand, error);
    }
    // The icosphere's inside, with a margin for its facets.
    const double r2 = (x - Vec3(0.05, -0.03, 0.02)).norm();
    signErrors += (r2 < 0.95 && d[n] > 0) || (r2 > 1.01 && d[n] < 0);
  }
  const double mean = sum / s.lattice.nodeCount();
  std::printf("%s: mean %.4f h, max %.4f h, band max %.2g h, largest under-estimate %.2g h, sign "
              "errors %lld\n",
    sweep == SweepMethod::ClosestPoint ? "closest-point sweep" : "Eikonal sweep", mean / s.h(),
    worst / s.h(), worstBand / s.h(), below / s.h(), signErrors);
  SW_CHECK(worstBand < 1e-5 * s.h(), "exact distances in the band");
  SW_CHECK(mean < meanBound * s.h() && worst < maxBound * s.h(),
    "the far field is near the exact distance");
  SW_CHECK(sweep != SweepMethod::ClosestPoint || below < 1e-5 * s.h(),
    "closest-point distances are those to true surface points: never below the exact distance");
  SW_CHECK(signErrors == 0, "inside negative, outside positive");
}

// A hole wider than the band lets the outside reach the inside: the votes disagree, and the winding
// number signs the field (TestWindingSign holds it to its reference).
void openMeshSignedByWindingNumber()
{
  Setup s;
  std::vector<std::array<int, 3>> kept; // a hole of several cells: the cap above z = 0.7
  for (const auto& t : s.soup.triangles)
  {
    if ((s.soup.points[t[0]] + s.soup.points[t[1]] + s.soup.points[t[2]]).z() / 3 < 0.7)
    {
      kept.push_back(t);
    }
  }
  s.soup.triangles = kept;
  std::vector<float> d(s.lattice.nodeCount());
  const SignedDistanceResult r = computeSignedDistance(s.soup, s.lattice, {}, d.data());
  SW_CHECK(r.completed && r.isSigned && r.signMethod == SignMethod::WindingNumber &&
      r.boundaryEdges > 0 && r.signDisagreements > 0,
    "an open sphere: the votes disagree, the winding number signs it (" << r.boundaryEdges
                                                                        << " boundary edges)");
  SignedDistanceSettings paper;
  paper.windingNumber = false;
  const SignedDistanceResult unsignedResult =
    computeSignedDistance(s.soup, s.lattice, paper, d.data());
  SW_CHECK(unsignedResult.completed && !unsignedResult.isSigned,
    "without the winding number it stays unsigned");
  bool nonNegative = true;
  for (float v : d)
  {
    nonNegative = nonNegative && v >= 0;
  }
  SW_CHECK(nonNegative, "an unsigned field has no negative value");
}

// The same sphere at the origin and moved to 1e9: the same errors in cells (issue #11). The grid is
// placed around the bounds, so the error depends on how coordinates that large are subtracted.
const TriangleSoup& icosphereAtOrigin()
{
  static const TriangleSoup soup = icosphere(3, Vec3::Zero(), 1.0);
  return soup;
}

double largestErrorAt(const Vec3& offset)
{
  TriangleSoup soup = icosphere(3, Vec3::Zero(), 1.0);
  for (Vec3& p : soup.points)
  {
    p += offset;
  }
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.5, 24, 0 }, lattice);
  std::vector<float> d(lattice.nodeCount());
  const SignedDistanceResult r = computeSignedDistance(soup, lattice, {}, d.data());
  double worst = 0;
  long long signErrors = 0;
  for (std::int64_t n = 0; n < lattice.nodeCount(); ++n)
  {
    const Vec3 local = lattice.position(lattice.coordinates(n)) - offset;
    const TriangleSoup& reference = icosphereAtOrigin();
    const double exact = testing::bruteForceDistance(reference, local);
    worst = std::max(worst, std::abs(std::abs(d[n]) - exact));
    signErrors += (local.norm() < 0.95 && d[n] > 0) || (local.norm() > 1.01 && d[n] < 0);
  }
  SW_CHECK(r.completed && r.isSigned && signErrors == 0,
    "the sphere at " << offset.x() << " is signed right");
  return worst / lattice.minSpacing();
}

void farFromTheOrigin()
{
  const double atOrigin = largestErrorAt(Vec3::Zero());
  const double far = largestErrorAt(Vec3(1e9, -1e9, 1e9));
  std::printf(
    "a unit sphere: largest error %.4f cells at the origin, %.4f cells at 1e9\n", atOrigin, far);
  SW_CHECK(far <= atOrigin + 0.01, "at 1e9 the same error in cells as at the origin");
}

void checksRefuse()
{
  TriangleSoup soup;
  SW_CHECK(!checkSoup(soup), "no triangles refused: " << checkSoup(soup).message());
  soup = icosphere(1);
  SW_CHECK(checkSoup(soup), "a sphere is fine");
  soup.points[3].x() = std::nan("");
  SW_CHECK(!checkSoup(soup), "NaN refused: " << checkSoup(soup).message());
  GridLattice huge;
  huge.dims = { 1 << 20, 1 << 20, 1 << 20 };
  SW_CHECK(
    !checkMemory(huge, {}), "a grid beyond memory refused: " << checkMemory(huge, {}).message());
}
} // namespace

int TestSignedDistance(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    outline();
    fieldAgainstExact(SweepMethod::ClosestPoint, 0.05, 0.5);
    fieldAgainstExact(SweepMethod::Eikonal, 0.5, 1.5);
    openMeshSignedByWindingNumber();
    checksRefuse();
    farFromTheOrigin();
  });
  return testing::finish("TestSignedDistance");
}
