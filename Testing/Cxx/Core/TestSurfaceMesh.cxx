// The editable surface mesh: one-rings of icospheres (eq. (9) counts), refused surfaces, and local
// edits (split, flip, collapse) whose vertex data follows them; a commit's rings, rebuilt only
// where the edits touched, equal those of the surface built anew; a part removed whole.
#include "Remeshing/EdgeSplits.h"
#include "Remeshing/Remesher.h"
#include "Surface/Icosphere.h"
#include "Surface/SurfaceGeometry.h"
#include "Surface/SurfaceMesh.h"
#include "TestUtilities.h"

#include <vtkSMPTools.h>

namespace
{
using namespace shrinkwrap;
using testing::meshOf;

void icospheres()
{
  const long long expected[7] = { 12, 42, 162, 642, 2562, 10242, 40962 };
  for (int s = 0; s <= 6; ++s)
  {
    const TriangleSoup sphere = icosphere(s, Vec3(1, 2, 3), 2.0);
    SW_CHECK(static_cast<long long>(sphere.points.size()) == expected[s] &&
        icosphereVertexCount(s) == expected[s],
      "icosphere level " << s << " has " << expected[s] << " vertices (eq. (9))");
    if (s > 4)
    {
      continue;
    }
    const SurfaceMesh mesh = meshOf(sphere);
    int ringEntries = 0;
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      ringEntries += mesh.valence(i);
      // Counter-clockwise rings: consecutive neighbours j, k make triangle (i, j, k) of the mesh.
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const auto& t = mesh.triangles()[mesh.ringTriangle(p)];
        const int j = mesh.ring(p), k = mesh.ring(mesh.next(i, p));
        const bool matches = (t[0] == i && t[1] == j && t[2] == k) ||
          (t[1] == i && t[2] == j && t[0] == k) || (t[2] == i && t[0] == j && t[1] == k);
        SW_CHECK(matches, "ring entry " << p << " of vertex " << i << " names its triangle");
      }
    }
    SW_CHECK(ringEntries == 3 * mesh.triangleCount(), "ring entries = 2 E = 3 T on level " << s);
    const double volume = enclosedVolume(mesh, sphere.points);
    SW_CHECK(volume > 0 && volume < 4.0 / 3.0 * M_PI * 8.0,
      "outward orientation, inscribed volume on level " << s);
  }
}

void refusedSurfaces()
{
  SurfaceMesh mesh;
  std::string error;
  const TriangleSoup tet{ { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } } };
  using testing::builds;
  SW_CHECK(builds(tet.points, tet.triangles, mesh, error), "a tetrahedron is a closed surface");
  SW_CHECK(!builds({}, {}, mesh, error), "empty surface refused: " << error);
  TriangleSoup isolated = tet;
  isolated.points.push_back({ 5, 5, 5 });
  SW_CHECK(!builds(isolated.points, isolated.triangles, mesh, error),
    "isolated vertex refused: " << error);
  TriangleSoup open = tet;
  open.triangles.pop_back();
  SW_CHECK(!builds(open.points, open.triangles, mesh, error), "open surface refused: " << error);
  TriangleSoup fin = tet; // a third triangle on edge (0, 1)
  fin.points.push_back({ 0.5, -1, 0 });
  fin.triangles.push_back({ 0, 1, 4 });
  SW_CHECK(!builds(fin.points, fin.triangles, mesh, error), "non-manifold edge refused: " << error);
  TriangleSoup flipped = tet;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  SW_CHECK(!builds(flipped.points, flipped.triangles, mesh, error),
    "inconsistent orientation refused: " << error);
  TriangleSoup nan = tet;
  nan.points[1].x() = std::nan("");
  SW_CHECK(!builds(nan.points, nan.triangles, mesh, error), "NaN refused: " << error);
}

// Every triangle (i, j, k) of the mesh appears in the rings of i, j and k as counter-clockwise
// neighbours: the rings were rebuilt after the edits.
bool ringsMatch(const SurfaceMesh& mesh)
{
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      const auto& t = mesh.triangles()[mesh.ringTriangle(p)];
      const int j = mesh.ring(p), k = mesh.ring(mesh.next(i, p));
      const bool found = (t[0] == i && t[1] == j && t[2] == k) ||
        (t[1] == i && t[2] == j && t[0] == k) || (t[2] == i && t[0] == j && t[1] == k);
      if (!found)
      {
        return false;
      }
    }
  }
  return true;
}

void edits()
{
  const TriangleSoup sphere = icosphere(1);
  SurfaceMesh mesh = meshOf(sphere);
  const VertexProperty<Vec3> velocity = mesh.addVertexProperty<Vec3>("v:velocity", Vec3::Zero());
  const VertexProperty<double> size = mesh.addVertexProperty<double>("v:size", 1.0);
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    velocity[i] = Vec3(i, 2 * i, 0);
    size[i] = 3 * i;
  }
  SW_CHECK(!mesh.vertexProperty<double>("v:velocity") && !mesh.vertexProperty<double>("v:none"),
    "a property asked for with another type, or none, gives a false handle");
  const int a = 0, b = mesh.ring(mesh.ringBegin(0));
  const double volume = enclosedVolume(mesh, mesh.points());

  // Split: the new vertex interpolates positions and every vertex data; 2 triangles become 4.
  const int m = mesh.split(a, b, 0.25);
  SW_CHECK(m == 42 && mesh.edited() && mesh.commit(), "a split commits");
  SW_CHECK(mesh.vertexCount() == 43 && mesh.triangleCount() == 82 && ringsMatch(mesh),
    "one vertex, two triangles more");
  SW_CHECK(
    (mesh.points()[m] - (0.75 * sphere.points[a] + 0.25 * sphere.points[b])).norm() < 1e-15 &&
      (mesh.vertexProperty<Vec3>("v:velocity")[m] - Vec3(0.25 * b, 0.5 * b, 0)).norm() < 1e-12 &&
      std::abs(mesh.vertexProperty<double>("v:size")[m] - 0.75 * b) < 1e-12,
    "the new vertex's position, velocity and size are interpolated");
  SW_CHECK(mesh.ringEntry(a, b) < 0 && mesh.ringEntry(a, m) >= 0 && mesh.ringEntry(m, b) >= 0,
    "(a, b) became (a, m, b)");
  SW_CHECK(std::abs(enclosedVolume(mesh, mesh.points()) - volume) < 1e-12,
    "a split on the edge keeps the volume");

  // Flip (a, m) back and forth: the same triangles again.
  const int c = mesh.ring(mesh.next(a, mesh.ringEntry(a, m)));
  const int d = mesh.ring(mesh.previous(a, mesh.ringEntry(a, m)));
  const auto before = mesh.triangles();
  SW_CHECK(mesh.flip(a, m) && mesh.commit() && mesh.ringEntry(c, d) >= 0 &&
      mesh.ringEntry(a, m) < 0 && ringsMatch(mesh),
    "a flip replaces (a, m) by (c, d)");
  SW_CHECK(!mesh.flip(a, m) && mesh.commit(), "a flip of an edge that is gone is refused");

  // Collapse m into b: the split undone, with b's data kept and the count back to the icosphere's.
  SW_CHECK(
    mesh.flip(d, c) && mesh.commit() && mesh.triangles().size() == before.size(), "flipped back");
  SW_CHECK(mesh.collapse(b, m, sphere.points[b]) && mesh.commit(), "a collapse commits");
  SW_CHECK(mesh.vertexCount() == 42 && mesh.triangleCount() == 80 && ringsMatch(mesh) &&
      mesh.vertexProperty<Vec3>("v:velocity")[b] == Vec3(b, 2 * b, 0) &&
      mesh.vertexProperty<double>("v:size")[b] == 3 * b,
    "the icosphere's counts again, b's velocity and size kept");
  SurfaceMesh copy = mesh;
  copy.vertexProperty<double>("v:size")[0] = -1;
  copy.removeVertexProperty("v:velocity");
  SW_CHECK(mesh.vertexProperty<double>("v:size")[0] == 0 &&
      mesh.vertexProperty<Vec3>("v:velocity") && !copy.vertexProperty<Vec3>("v:velocity"),
    "a copy's properties are its own");
  SW_CHECK(
    std::abs(enclosedVolume(mesh, mesh.points()) - volume) < 1e-12, "the same surface again");

  // Edits see each other before the commit: every edge split once, in one pass.
  SurfaceMesh all = meshOf(sphere);
  const std::vector<std::array<int, 2>> edges = edgesOf(all);
  int splits = 0;
  for (const auto& e : edges)
  {
    splits += all.split(e[0], e[1]) >= 0;
  }
  SW_CHECK(splits == 120 && all.commit() && all.vertexCount() == 162 &&
      all.triangleCount() == 320 && ringsMatch(all),
    "120 splits in one pass: level 2's counts, closed");
}

// The rings a commit leaves (the untouched vertices' renumbered, the others' walked again) entry
// for entry equal those of SurfaceMesh::build on the same points and triangles.
bool sameAsBuilt(const SurfaceMesh& mesh)
{
  SurfaceMesh built;
  if (!SurfaceMesh::build(mesh.points(), mesh.triangles(), built) ||
    built.vertexCount() != mesh.vertexCount())
  {
    return false;
  }
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    if (built.ringBegin(i) != mesh.ringBegin(i) || built.ringEnd(i) != mesh.ringEnd(i))
    {
      return false;
    }
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      if (built.ring(p) != mesh.ring(p) || built.ringTriangle(p) != mesh.ringTriangle(p))
      {
        return false;
      }
    }
  }
  return true;
}

void commitsAsBuilt()
{
  // A level-3 sphere squashed to an ellipsoid, so that its edges differ in length: rounds of
  // splits, collapses (which renumber) and flips, each compared with the surface built anew.
  TriangleSoup sphere = icosphere(3);
  for (Vec3& x : sphere.points)
  {
    x.z() *= 0.3;
  }
  SurfaceMesh mesh = meshOf(sphere);
  int rounds = 0, edits = 0;
  for (const double length : { 0.12, 0.2, 0.35 })
  {
    CollapseSettings collapses;
    collapses.avoidCrossings = false;
    const int splits = splitLongEdges(mesh, 4.0 / 3.0 * length);
    rounds += sameAsBuilt(mesh);
    const int collapsed = collapseShortEdges(mesh, 0.8 * length, 4.0 / 3.0 * length, collapses);
    rounds += sameAsBuilt(mesh);
    FlipSettings flips;
    flips.avoidCrossings = false;
    const int flipped = equalizeValences(mesh, flips);
    rounds += sameAsBuilt(mesh);
    std::printf("edge length %.2f: %d splits, %d collapses, %d flips, %d vertices\n", length,
      splits, collapsed, flipped, mesh.vertexCount());
    edits += splits + collapsed + flipped;
  }
  SW_CHECK(rounds == 9 && edits > 300,
    "after each of 9 rounds (" << edits << " edits) the rings equal a fresh build's");
}

// Three spheres in one mesh: removing the middle one's part leaves the other two closed, with their
// vertex data; a vertex that is none removes nothing.
void removedParts()
{
  TriangleSoup three;
  for (int k = 0; k < 3; ++k)
  {
    const TriangleSoup one = icosphere(k + 1, Vec3(3.0 * k, 0, 0));
    const int first = static_cast<int>(three.points.size());
    three.points.insert(three.points.end(), one.points.begin(), one.points.end());
    for (const auto& t : one.triangles)
    {
      three.triangles.push_back({ first + t[0], first + t[1], first + t[2] });
    }
  }
  SurfaceMesh mesh = meshOf(three);
  auto id = mesh.addVertexProperty<double>("v:x", 0);
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    id[i] = mesh.points()[i].x();
  }
  const int removed = mesh.removePart(42 + 5); // a vertex of the level-2 sphere (162 vertices)
  const bool committed = static_cast<bool>(mesh.commit());
  id = mesh.vertexProperty<double>("v:x");
  bool dataFollows = true;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    dataFollows = dataFollows && id[i] == mesh.points()[i].x() && std::abs(id[i] - 3.0) > 1.5;
  }
  SW_CHECK(removed == 162 && committed && mesh.vertexCount() == 42 + 642 &&
      mesh.triangleCount() == 80 + 1280 && sameAsBuilt(mesh) && dataFollows,
    "the middle sphere's part removed (" << removed << " vertices), the others closed");
  SW_CHECK(mesh.removePart(-1) == 0 && mesh.removePart(mesh.vertexCount()) == 0,
    "no vertex, no part removed");
}

} // namespace

int TestSurfaceMesh(int, char*[])
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [] {
    icospheres();
    refusedSurfaces();
    edits();
    commitsAsBuilt();
    removedParts();
  });
  return testing::finish("TestSurfaceMesh");
}
