// Isotropic remeshing (groundwork of issue #10): a coarse sphere refined and a fine one coarsened to
// the target edge length, closed, same genus, the shape kept, valences near 6, good angles; vertex data
// follows the edits; refused settings.
#include "Icosphere.h"
#include "Remesher.h"
#include "SurfaceGeometry.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

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
    s.thin += smallestAngle(mesh.points()[t[0]], mesh.points()[t[1]], mesh.points()[t[2]]) < 20 * M_PI / 180;
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
  std::printf("%s: level %d to L = %.3f: %d splits, %d collapses, %d flips -> %d vertices; edges in "
              "[4/5, 4/3] L %.1f%%, valence 5-7 %.1f%%, angles < 20 deg %.1f%%, volume %+.2f%%\n",
    what, level, L, r.splits, r.collapses, r.flips, mesh.vertexCount(), 100 * s.withinBand, 100 * s.valence6,
    100 * s.thin, 100 * change);
  SW_CHECK(r.status && closed, what << ": closed 2-manifold: " << error);
  SW_CHECK(mesh.vertexCount() - mesh.triangleCount() / 2 == 2, what << ": genus 0 kept");
  SW_CHECK(s.withinBand > 0.9 && s.valence6 > 0.9 && s.thin < 0.05, what << ": edges near L, valences near 6, few thin triangles");
  SW_CHECK(change < 0.03, what << ": the volume within 3%");
}

void dataFollows()
{
  // Vertex data equal to the positions stays equal through splits (interpolated both) and flips, when
  // no relaxation moves the positions alone; a collapse keeps the surviving vertex's data.
  SurfaceMesh mesh = testing::meshOf(icosphere(2));
  mesh.vertexData("copy") = mesh.points();
  RemeshSettings settings;
  settings.targetLength = 0.12;
  settings.relaxWeight = 0;
  settings.collapseBelow = 0.01;
  settings.iterations = 2;
  const RemeshReport r = remesh(mesh, settings);
  double worst = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    worst = std::max(worst, (mesh.vertexData("copy")[i] - mesh.points()[i]).norm());
  }
  SW_CHECK(r.splits > 0 && r.flips > 0 && worst < 1e-12, "vertex data follows splits and flips (" << worst << ")");
  SurfaceMesh fine = testing::meshOf(icosphere(3));
  std::vector<Vec3>& label = fine.vertexData("label");
  for (int i = 0; i < fine.vertexCount(); ++i)
  {
    label[i] = Vec3(i, 0, 0);
  }
  const int collapses = collapseShortEdges(fine, 0.2, 1.0, CollapseSettings());
  bool own = true; // every survivor's label is an old vertex's, in increasing order
  for (int i = 1; i < fine.vertexCount(); ++i)
  {
    own = own && fine.vertexData("label")[i].x() > fine.vertexData("label")[i - 1].x();
  }
  SW_CHECK(collapses > 0 && own && fine.vertexCount() == 642 - collapses, "collapses keep the survivors' data, in order");
}

void refused()
{
  SurfaceMesh mesh = testing::meshOf(icosphere(1));
  RemeshSettings settings;
  SW_CHECK(!remesh(mesh, settings).status && mesh.vertexCount() == 42, "L = 0 refused, the mesh untouched");
}
} // namespace

int TestRemesher(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    towards(2, 0.08, "refine");
    towards(5, 0.12, "coarsen");
    dataFollows();
    refused();
  });
  return testing::finish("TestRemesher");
}
