// The sign where the votes disagree (issue #11): the generalized winding number against its
// brute-force sum, and fields of surfaces with holes, overlaps, flipped faces and crossings signed
// as that reference says: no node farther than one cell from the surface on the wrong side (the bar
// allows 0.1%). A disc encloses nothing: unsigned.
#include "Distance/ConsistentOrientation.h"
#include "Distance/DistanceSource.h"
#include "Distance/SignedDistance.h"
#include "Distance/SoupEdges.h"
#include "Distance/WindingNumber.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <random>

namespace
{
using namespace shrinkwrap;

TriangleSoup sphere(const Vec3& center, double radius, int level = 3)
{
  return icosphere(level, center, radius);
}

TriangleSoup joined(const TriangleSoup& a, const TriangleSoup& b)
{
  TriangleSoup soup = a;
  const int offset = static_cast<int>(a.points.size());
  soup.points.insert(soup.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles)
  {
    soup.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  return soup;
}

void fastAgainstExact()
{
  const TriangleSoup soup = joined(sphere(Vec3::Zero(), 1), sphere(Vec3(0.8, 0.3, 0), 0.7));
  const WindingNumber w(soup);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-2, 2);
  double worst = 0;
  int wrongSide = 0;
  for (int s = 0; s < 2000; ++s)
  {
    const Vec3 x(u(random), u(random), u(random));
    const double fast = w.at(x), exact = w.exactAt(x);
    worst = std::max(worst, std::abs(fast - exact));
    wrongSide += (std::abs(fast) > 0.5) != (std::abs(exact) > 0.5);
  }
  std::printf("winding number: largest difference from the exact sum %.2e on 2000 points, %d on "
              "the other side of 1/2\n",
    worst, wrongSide);
  SW_CHECK(
    worst < 0.02 && wrongSide == 0, "the fast winding number is within 0.02 of the exact sum");
  SW_CHECK(std::abs(w.exactAt(Vec3(-0.5, 0, 0)) - 1) < 1e-9 &&
      std::abs(w.exactAt(Vec3(0.9, 0.3, 0)) - 2) < 1e-9 &&
      std::abs(w.exactAt(Vec3(3, 0, 0))) < 1e-9,
    "1 inside one sphere, 2 where two overlap, 0 outside");
}

struct Field
{
  SignedDistanceResult result;
  long long far = 0, wrong = 0;
};

// The field of `soup` on a grid of `resolution` cells, and how many nodes farther than a cell from
// the surface disagree with the brute-force winding number (inside: |w| > 1/2).
Field field(const TriangleSoup& soup, int resolution, SweepMethod sweep = SweepMethod::ClosestPoint)
{
  GridLattice lattice;
  placeGrid(soup.bounds(), GridPlacement{ 1.1, 0.5, resolution, 0 }, lattice);
  SignedDistanceSettings settings;
  settings.sweep = sweep;
  std::vector<float> d(lattice.nodeCount());
  Field f;
  f.result = computeSignedDistance(soup, lattice, settings, d.data());
  TriangleSoup oriented = weldDuplicatePoints(soup);
  orientConsistently(oriented);
  const WindingNumber reference(oriented);
  for (std::int64_t n = 0; n < lattice.nodeCount(); ++n)
  {
    if (std::abs(d[n]) > lattice.minSpacing())
    {
      ++f.far;
      f.wrong +=
        (d[n] < 0) != (std::abs(reference.exactAt(lattice.position(lattice.coordinates(n)))) > 0.5);
    }
  }
  return f;
}

void expectSigned(const std::string& name, const TriangleSoup& soup,
  SweepMethod sweep = SweepMethod::ClosestPoint, std::vector<int> resolutions = { 24, 48 })
{
  for (int resolution : resolutions)
  {
    const Field f = field(soup, resolution, sweep);
    std::printf("%-34s %3d cells: %s by %s, %lld of %lld far nodes on the wrong side, %lld by "
                "winding number, "
                "%lld reoriented, %lld unconfirmed triangles\n",
      name.c_str(), resolution, f.result.isSigned ? "signed" : "UNSIGNED",
      f.result.signMethod == SignMethod::WindingNumber
        ? "winding number"
        : (f.result.signMethod == SignMethod::Votes ? "votes" : "none"),
      f.wrong, f.far, f.result.windingEvaluations, f.result.reorientedTriangles,
      f.result.unconfirmedTriangles);
    SW_CHECK(f.result.completed && f.result.isSigned && f.wrong == 0,
      name << " at " << resolution
           << " cells: signed, every node farther than a cell on the winding number's side");
  }
}

TriangleSoup withoutTriangle(TriangleSoup soup, int t)
{
  soup.triangles.erase(soup.triangles.begin() + t);
  return soup;
}

TriangleSoup halfFlipped(TriangleSoup soup)
{
  for (std::size_t t = 0; t < soup.triangles.size(); t += 2)
  {
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
  }
  return soup;
}

// The cap above z = 0.3 pushed down through the bottom of the sphere.
TriangleSoup pushedThrough(TriangleSoup soup)
{
  for (Vec3& p : soup.points)
  {
    if (p.z() > 0.3)
    {
      p.z() -= 1.8;
    }
  }
  return soup;
}

TriangleSoup disc()
{
  TriangleSoup soup;
  soup.points.push_back(Vec3::Zero());
  for (int k = 0; k < 24; ++k)
  {
    soup.points.emplace_back(std::cos(k * M_PI / 12), std::sin(k * M_PI / 12), 0);
    soup.triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 24 });
  }
  return soup;
}
} // namespace

int TestWindingSign(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    fastAgainstExact();
    const TriangleSoup ball = sphere(Vec3(0.05, -0.03, 0.02), 1);
    expectSigned("a sphere missing one triangle", withoutTriangle(ball, 17));
    // An icosahedron missing a face: the hole is wider than the band (which seals the sphere's
    // small one), the votes disagree (the field was unsigned, silently, before issue #11).
    expectSigned("an icosahedron missing a face",
      withoutTriangle(sphere(Vec3(0.05, -0.03, 0.02), 1, 0), 7), SweepMethod::ClosestPoint,
      { 48, 64 });
    expectSigned("a sphere missing its cap", [&] {
      TriangleSoup s = ball;
      s.triangles.erase(std::remove_if(s.triangles.begin(), s.triangles.end(),
                          [&](const auto& t) {
                            return (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]).z() / 3 > 0.7;
                          }),
        s.triangles.end());
      return s;
    }());
    expectSigned("two overlapping spheres", joined(ball, sphere(Vec3(0.9, 0.2, 0.1), 0.7)));
    expectSigned("half the faces flipped", halfFlipped(ball));
    expectSigned("a sphere pushed through itself", pushedThrough(ball));
    expectSigned("open and overlapping, Eikonal sweep",
      joined(withoutTriangle(ball, 17), sphere(Vec3(0.9, 0.2, 0.1), 0.7)), SweepMethod::Eikonal);
    const Field flat = field(disc(), 24);
    SW_CHECK(flat.result.completed && !flat.result.isSigned, "a disc encloses nothing: unsigned");
  });
  return testing::finish("TestWindingSign");
}
