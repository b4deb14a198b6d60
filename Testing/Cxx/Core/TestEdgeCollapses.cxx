// Edge collapses: needles and caps merged away, the genus and the link condition kept.
#include "Remeshing/EdgeCollapses.h"
#include "Surface/Icosphere.h"
#include "Surface/SurfaceGeometry.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

#include <algorithm>

namespace
{
using namespace shrinkwrap;
using testing::meshOf;

// Euler characteristic V - E + F of a closed triangle surface: V - F / 2.
int eulerCharacteristic(
  const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
{
  return static_cast<int>(points.size()) - static_cast<int>(triangles.size()) / 2;
}

void edgeCollapses()
{
  // A needle: one vertex of an icosphere moved to within 1% of a neighbour.
  TriangleSoup needle = icosphere(3);
  const SurfaceMesh mesh = meshOf(needle);
  const int a = 0, b = mesh.ring(mesh.ringBegin(0));
  needle.points[a] = needle.points[b] + 0.01 * (needle.points[a] - needle.points[b]);
  SurfaceMesh after = mesh;
  after.points() = needle.points;
  const VertexProperty<int> label = after.addVertexProperty<int>("v:label", -1);
  for (int i = 0; i < after.vertexCount(); ++i)
  {
    label[i] = i;
  }
  const int n = collapseEdges(after, CollapseSettings());
  const std::vector<Vec3> points = after.points();
  const std::vector<std::array<int, 3>> triangles = after.triangles();
  SurfaceMesh rebuilt;
  std::string error;
  const bool closed = testing::builds(points, triangles, rebuilt, error);
  int relabelled = 0; // vertices whose data is not their own: at most the one after the merged pair
  for (int i = 0; i < after.vertexCount(); ++i)
  {
    const int own = after.vertexProperty<int>("v:label")[i];
    relabelled += own != i && own != i + 1;
  }
  std::printf(
    "edge collapses: a needle of %.2f degrees, %d collapse(s), smallest angle then %.1f degrees\n",
    smallestAngle(mesh, needle.points).angle * 180 / M_PI, n,
    closed ? smallestAngle(after, points).angle * 180 / M_PI : 0.0);
  SW_CHECK(n == 1 && closed, "one collapse, a closed 2-manifold: " << error);
  SW_CHECK(points.size() == needle.points.size() - 1 && eulerCharacteristic(points, triangles) == 2,
    "one vertex fewer, same genus");
  SW_CHECK(relabelled == 0 && after.vertexProperty<int>("v:label").values().size() == points.size(),
    "vertex data follows the collapse (each vertex keeps its own, renumbered)");
  SW_CHECK(smallestAngle(after, points).angle > 20 * M_PI / 180, "no thin triangle left");

  // A cap: a vertex of valence 3 put into a face, almost on one of its edges. The flat triangle
  // goes with it.
  TriangleSoup cap = icosphere(2);
  const std::array<int, 3> face = cap.triangles[7];
  const Vec3 centre = (cap.points[face[0]] + cap.points[face[1]] + cap.points[face[2]]) / 3;
  const Vec3 middle = 0.5 * (cap.points[face[0]] + cap.points[face[1]]);
  const int v = static_cast<int>(cap.points.size());
  cap.points.push_back(middle + 0.01 * (centre - middle));
  cap.triangles[7] = { face[0], face[1], v };
  cap.triangles.push_back({ face[1], face[2], v });
  cap.triangles.push_back({ face[2], face[0], v });
  SurfaceMesh capped = meshOf(cap);
  SW_CHECK(collapseEdges(capped, CollapseSettings()) == 1 && capped.vertexCount() == 162 &&
      capped.triangleCount() == 320 &&
      testing::builds(capped.points(), capped.triangles(), rebuilt, error),
    "the cap's vertex is merged away: the icosphere's counts again, closed");

  // Where the two ends of an edge share a third neighbour, merging them would pinch the surface:
  // the two-vertex-wide waist of a tetrahedron-like cap is left alone (link condition).
  TriangleSoup tetra;
  tetra.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.001, 0.001, 1) };
  tetra.triangles = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 } };
  SurfaceMesh waist = meshOf(tetra);
  SW_CHECK(collapseEdges(waist, CollapseSettings()) == 0,
    "no collapse leaves fewer than four vertices or breaks the link condition");
}

// A needle (a, b) beside a vertex of valence 3 merges that vertex away first, into a where a
// stands; but where the lone vertex holds a rim (kAnchor), a merges into it there instead.
void loneVertexAnchored()
{
  TriangleSoup cap = icosphere(2);
  const std::array<int, 3> face = cap.triangles[7];
  const int v = static_cast<int>(cap.points.size());
  const Vec3 lone = (cap.points[face[0]] + cap.points[face[1]] + cap.points[face[2]]) / 3;
  cap.points.push_back(lone);
  cap.triangles[7] = { face[0], face[1], v };
  cap.triangles.push_back({ face[1], face[2], v });
  cap.triangles.push_back({ face[2], face[0], v });
  cap.points[face[0]] = cap.points[face[1]] + 0.01 * (cap.points[face[0]] - cap.points[face[1]]);
  auto keeps = [&](bool anchored) {
    SurfaceMesh mesh = meshOf(cap);
    if (anchored)
    {
      mesh.addVertexProperty<double>(kAnchor, 0)[v] = 1;
    }
    const int n = collapseEdges(mesh, CollapseSettings());
    const bool found =
      std::find(mesh.points().begin(), mesh.points().end(), lone) != mesh.points().end();
    std::printf("lone vertex %s: %d collapse(s), its position %s\n", anchored ? "anchored" : "free",
      n, found ? "kept" : "gone");
    return n > 0 && found;
  };
  SW_CHECK(keeps(true) && !keeps(false),
    "an anchored lone vertex keeps its place; a free one merges into a");
}

} // namespace

int TestEdgeCollapses(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    edgeCollapses();
    loneVertexAnchored();
  });
  return testing::finish("TestEdgeCollapses");
}
