// Isotropic remeshing (groundwork of issue #10): a coarse sphere refined and a fine one coarsened
// to the target edge length, closed, same genus, the shape kept, valences near 6, good angles;
// vertex data follows the edits; anchored vertices stay in place through collapses; adaptive sizes
// from the curvature; refused settings; a stop within a pass.
#include "Remeshing/Remesher.h"
#include "Surface/Icosphere.h"
#include "Surface/SurfaceGeometry.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

namespace
{
using namespace shrinkwrap;

struct Spread
{
  double withinBand = 0; // share of edges in [4/5 L, 4/3 L]
  double valence6 = 0;   // share of vertices of valence 5 to 7
  double thin = 0;       // share of triangles with an angle under 20 degrees
};

Spread spreadOf(const SurfaceMesh& mesh, double L)
{
  Spread s;
  int edges = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    s.valence6 += mesh.valence(i) >= 5 && mesh.valence(i) <= 7;
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      const double l = (mesh.points()[i] - mesh.points()[mesh.ring(p)]).norm();
      s.withinBand += l >= 0.8 * L * 0.99 && l <= 4.0 / 3.0 * L * 1.01;
      ++edges;
    }
  }
  for (const auto& t : mesh.triangles())
  {
    s.thin += smallestAngle(mesh.points()[t[0]], mesh.points()[t[1]], mesh.points()[t[2]]) <
      20 * M_PI / 180;
  }
  s.withinBand /= edges;
  s.valence6 /= mesh.vertexCount();
  s.thin /= mesh.triangleCount();
  return s;
}

void towards(int level, double L, const char* what)
{
  SurfaceMesh mesh = testing::meshOf(icosphere(level));
  const double volume = enclosedVolume(mesh, mesh.points());
  RemeshSettings settings;
  settings.targetLength = L;
  const RemeshReport r = remesh(mesh, settings);
  const Spread s = spreadOf(mesh, L);
  SurfaceMesh rebuilt;
  std::string error;
  const bool closed = testing::builds(mesh.points(), mesh.triangles(), rebuilt, error);
  const double change = std::abs(enclosedVolume(mesh, mesh.points()) - volume) / volume;
  std::printf(
    "%s: level %d to L = %.3f: %d splits, %d collapses, %d flips -> %d vertices; edges in "
    "[4/5, 4/3] L %.1f%%, valence 5-7 %.1f%%, angles < 20 deg %.1f%%, volume %+.2f%%\n",
    what, level, L, r.splits, r.collapses, r.flips, mesh.vertexCount(), 100 * s.withinBand,
    100 * s.valence6, 100 * s.thin, 100 * change);
  SW_CHECK(r.status && closed, what << ": closed 2-manifold: " << error);
  SW_CHECK(mesh.vertexCount() - mesh.triangleCount() / 2 == 2, what << ": genus 0 kept");
  SW_CHECK(s.withinBand > 0.9 && s.valence6 > 0.9 && s.thin < 0.05,
    what << ": edges near L, valences near 6, few thin triangles");
  SW_CHECK(change < 0.03, what << ": the volume within 3%");
}

void dataFollows()
{
  // Vertex data equal to the positions stays equal through splits (interpolated both) and flips,
  // when no relaxation moves the positions alone; a collapse keeps the surviving vertex's data.
  SurfaceMesh mesh = testing::meshOf(icosphere(2));
  const VertexProperty<Vec3> copy = mesh.addVertexProperty<Vec3>("v:copy", Vec3::Zero());
  copy.values() = mesh.points();
  RemeshSettings settings;
  settings.targetLength = 0.12;
  settings.relaxWeight = 0;
  settings.collapseBelow = 0.01;
  settings.iterations = 2;
  const RemeshReport r = remesh(mesh, settings);
  double worst = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    worst = std::max(worst, (mesh.vertexProperty<Vec3>("v:copy")[i] - mesh.points()[i]).norm());
  }
  SW_CHECK(r.splits > 0 && r.flips > 0 && worst < 1e-12,
    "vertex data follows splits and flips (" << worst << ")");
  SurfaceMesh fine = testing::meshOf(icosphere(3));
  const VertexProperty<int> label = fine.addVertexProperty<int>("v:label", -1);
  for (int i = 0; i < fine.vertexCount(); ++i)
  {
    label[i] = i;
  }
  const int collapses = collapseShortEdges(fine, 0.2, 1.0, CollapseSettings());
  bool own = true; // every survivor's label is an old vertex's, in increasing order
  for (int i = 1; i < fine.vertexCount(); ++i)
  {
    own =
      own && fine.vertexProperty<int>("v:label")[i] > fine.vertexProperty<int>("v:label")[i - 1];
  }
  SW_CHECK(collapses > 0 && own && fine.vertexCount() == 642 - collapses,
    "collapses keep the survivors' data, in order");
}

// Collapses merge into an anchored end at its position (kAnchor, e.g. a vertex holding a target's
// rim): anchors on an independent set of a sphere's vertices all keep their positions through a
// coarsening that without them moves some.
void anchorsStay()
{
  SurfaceMesh plain = testing::meshOf(icosphere(3));
  std::vector<double> anchors(plain.vertexCount(), 0.0);
  std::vector<Vec3> anchored; // positions
  for (int i = 0; i < plain.vertexCount(); ++i)
  {
    bool free = true; // no anchored neighbour
    for (int p = plain.ringBegin(i); p < plain.ringEnd(i); ++p)
    {
      free = free && anchors[plain.ring(p)] == 0;
    }
    if (free && i % 3 == 0)
    {
      anchors[i] = 1;
      anchored.push_back(plain.points()[i]);
    }
  }
  SurfaceMesh fixed = plain;
  fixed.addVertexProperty<double>(kAnchor, 0).values() = anchors;
  auto kept = [&](const SurfaceMesh& mesh) {
    int n = 0;
    for (const Vec3& a : anchored)
    {
      n += std::find(mesh.points().begin(), mesh.points().end(), a) != mesh.points().end();
    }
    return n;
  };
  const int withAnchors = collapseShortEdges(fixed, 0.2, 1.0, CollapseSettings());
  const int without = collapseShortEdges(plain, 0.2, 1.0, CollapseSettings());
  const int n = static_cast<int>(anchored.size());
  SW_CHECK(withAnchors > 0 && kept(fixed) == n && kept(plain) < n,
    "anchored vertices keep their places through collapses ("
      << kept(fixed) << " of " << n << "; without anchors " << kept(plain) << ", " << without
      << " collapses)");
}

// Passes after the first look only at the edges the last pass found short or moved an end of, and
// splits only at the new vertices: yet a fresh pass over every edge afterwards finds nothing left,
// on a level-5 sphere coarsened to twice its edge length (a dozen collapse passes, as a contour
// start takes) and on a level-0 one refined, whose splits take several passes.
void laterPassesMissNothing()
{
  SurfaceMesh fine = testing::meshOf(icosphere(5));
  const double L = 0.08; // twice the edges of level 5 on the unit sphere
  const int collapses = collapseShortEdges(fine, 0.8 * L, 4.0 / 3.0 * L, CollapseSettings());
  const int again = collapseShortEdges(fine, 0.8 * L, 4.0 / 3.0 * L, CollapseSettings());
  SurfaceMesh coarse = testing::meshOf(icosphere(0));
  const int splits = splitLongEdges(coarse, 0.1);
  const int more = splitLongEdges(coarse, 0.1);
  std::printf("later passes: %d collapses (10242 -> %d vertices), then %d; %d splits, then %d\n",
    collapses, fine.vertexCount(), again, splits, more);
  SW_CHECK(collapses > 5000 && again == 0,
    "a fresh collapse pass after the incremental ones finds no edge left");
  SW_CHECK(
    splits > 100 && more == 0, "a fresh split pass after the incremental ones finds no edge left");
}

// Adaptive sizing: on a sphere of radius R every vertex gets the chord-error length sqrt(6 e R - 3
// e^2); an ellipsoid remeshed adaptively gets shorter edges at its sharp ends than at its flat
// waist, and more of them than with L alone there.
void adaptive()
{
  SurfaceMesh sphere = testing::meshOf(icosphere(4, Vec3::Zero(), 2.0));
  RemeshSettings settings;
  settings.targetLength = 0.2;
  settings.shortest = 0.25;
  settings.longest = 4;
  settings.chordError = 0.05;
  assignEdgeSizes(sphere, settings);
  const double e = 0.05 * 0.2, expected = std::sqrt(6 * e * 2.0 - 3 * e * e) / 0.2;
  double low = 1e9, high = 0;
  for (const double s : sphere.vertexValues<double>(kEdgeSize))
  {
    low = std::min(low, s);
    high = std::max(high, s);
  }
  std::printf(
    "sizes on a sphere of radius 2: %.3f to %.3f L (chord error: %.3f L)\n", low, high, expected);
  SW_CHECK(low > 0.95 * expected && high < 1.01 * expected,
    "the sphere's sizes are the chord-error length (within 5%)");

  // x^2 / 9 + y^2 + z^2 = 1: curvature 3 at the ends (x = +-3), 1/3 to 1 at the waist.
  auto ellipsoid = [] {
    SurfaceMesh mesh = testing::meshOf(icosphere(4));
    for (Vec3& p : mesh.points())
    {
      p.x() *= 3;
    }
    return mesh;
  };
  auto meanEdge = [](const SurfaceMesh& mesh, bool ends) {
    double sum = 0;
    int count = 0;
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      const bool atEnd = std::abs(mesh.points()[i].x()) > 2.7,
                 atWaist = std::abs(mesh.points()[i].x()) < 1;
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        if ((ends && atEnd) || (!ends && atWaist))
        {
          sum += (mesh.points()[mesh.ring(p)] - mesh.points()[i]).norm();
          ++count;
        }
      }
    }
    return sum / count;
  };
  SurfaceMesh uniform = ellipsoid(), adapted = ellipsoid();
  RemeshSettings r;
  r.targetLength = 0.25;
  remesh(uniform, r);
  r.shortest = 0.4;
  r.longest = 1.6;
  r.chordError = 0.05;
  const RemeshReport report = remesh(adapted, r);
  const Spread s = spreadOf(adapted, 0.25);
  std::printf(
    "ellipsoid at L = 0.25: uniform %d vertices, ends %.3f, waist %.3f; adaptive %d vertices, ends "
    "%.3f, waist %.3f; angles < 20 deg %.1f%%\n",
    uniform.vertexCount(), meanEdge(uniform, true), meanEdge(uniform, false), adapted.vertexCount(),
    meanEdge(adapted, true), meanEdge(adapted, false), 100 * s.thin);
  SW_CHECK(report.status && meanEdge(adapted, true) < 0.75 * meanEdge(adapted, false),
    "adaptive: the sharp ends get shorter edges than the flat waist");
  SW_CHECK(meanEdge(adapted, true) < 0.8 * meanEdge(uniform, true) && s.thin < 0.05,
    "shorter than L alone there, with few thin triangles");
  SW_CHECK(!adapted.vertexProperty<double>(kEdgeSize), "the sizes are gone after the remeshing");
}

void refused()
{
  SurfaceMesh mesh = testing::meshOf(icosphere(1));
  RemeshSettings settings;
  SW_CHECK(!remesh(mesh, settings).status && mesh.vertexCount() == 42,
    "L = 0 refused, the mesh untouched");
}
// Issue #61: a stop asked for ends a pass's edits early (StopPoll: by its 8th vertex, or within the
// crossing guard's grid at its first question), leaving a closed surface with the edits made so
// far; splits stop before their first pass. A stop never asked for changes nothing, asked once a
// pass and then at most every 0.1 s.
void stopsWithinAPass()
{
  int asked = 0;
  const std::function<bool()> yes = [&] { return ++asked > 0; };
  const std::function<bool()> no = [&] { return ++asked < 0; };
  SurfaceMesh fine = testing::meshOf(icosphere(5)), whole = fine, split = fine;
  const CollapseSettings collapses;
  const int stopped = collapseShortEdges(fine, 0.1, 0.2, collapses, yes);
  const int askedStopped = asked;
  SurfaceMesh rebuilt;
  const bool closed =
    static_cast<bool>(SurfaceMesh::build(fine.points(), fine.triangles(), rebuilt));
  asked = 0;
  const int all = collapseShortEdges(whole, 0.1, 0.2, collapses, no);
  SW_CHECK(
    stopped <= 8 && askedStopped == 1 && closed && all > 1000 && asked <= 10242 / 64 * 16 + 16,
    "collapses stopped at the first ask (" << stopped << " of " << all << "; asked " << askedStopped
                                           << " time, and " << asked << " times unstopped)");
  SW_CHECK(splitLongEdges(split, 0.01, yes) == 0 && split.vertexCount() == 10242,
    "splits stopped before their first pass");
}
} // namespace

int TestRemesher(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    towards(2, 0.08, "refine");
    towards(5, 0.12, "coarsen");
    dataFollows();
    anchorsStay();
    laterPassesMissNothing();
    adaptive();
    refused();
    stopsWithinAPass();
  });
  return testing::finish("TestRemesher");
}
