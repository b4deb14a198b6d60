#include "Remeshing/EdgeCollapses.h"

#include "Surface/SurfaceGeometry.h"

#include <utility>

namespace shrinkwrap
{

namespace
{
// Only the two vertices opposite the edge (a, b) are neighbours of both; otherwise merging a and b
// would pinch the surface.
bool linkCondition(const SurfaceMesh& mesh, int a, int b)
{
  int common = 0;
  for (int p = mesh.ringBegin(a); p < mesh.ringEnd(a); ++p)
  {
    common += mesh.ringEntry(b, mesh.ring(p)) >= 0;
  }
  return common == 2;
}

// The triangles around a and b other than the two on the edge keep their orientation when a and b
// move to m; degenerating ones have no reliable normal to keep: they are left out, or
// (orientDegenerate) must only face the way the fan does.
bool keepsNormals(const SurfaceMesh& mesh, const std::vector<Vec3>& x, int a, int b, const Vec3& m,
  const CollapseSettings& settings)
{
  bool keeps = true;
  Vec3 fan = Vec3::Zero(); // area-weighted normal of the fan before
  if (settings.orientDegenerate)
  {
    forEachFanTriangle(
      mesh, a, b, [&](int v, int u, int w) { fan += (x[u] - x[v]).cross(x[w] - x[v]); });
  }
  forEachFanTriangle(mesh, a, b, [&](int v, int u, int w) {
    if (!keeps)
    {
      return;
    }
    const Vec3 before = (x[u] - x[v]).cross(x[w] - x[v]);
    const Vec3 after = (x[u] - m).cross(x[w] - m);
    if (smallestAngleBelow(x[v], x[u], x[w], settings.maxAngle))
    {
      keeps = !settings.orientDegenerate || after.dot(fan) > 0;
      return;
    }
    const double lengths = before.norm() * after.norm();
    keeps = lengths > 0 && before.dot(after) >= settings.minNormalDot * lengths;
  });
  return keeps;
}

} // namespace

Merge mergeOf(const std::vector<Vec3>& x, const std::vector<double>& anchors, int a, int b)
{
  const double ha = anchors.empty() ? 0 : anchors[a], hb = anchors.empty() ? 0 : anchors[b];
  if (ha > 0 || hb > 0)
  {
    return ha >= hb ? Merge{ a, b, x[a] } : Merge{ b, a, x[b] };
  }
  return { a, b, 0.5 * (x[a] + x[b]) };
}

bool collapseIsOk(const SurfaceMesh& mesh, const std::vector<Vec3>& x, int keep, int gone,
  const Vec3& m, const CollapseSettings& settings)
{
  const int p = mesh.ringEntry(keep, gone);
  const int c = mesh.ring(mesh.next(keep, p)), d = mesh.ring(mesh.previous(keep, p));
  return !(mesh.valence(c) <= 3 || mesh.valence(d) <= 3 ||
    mesh.valence(keep) + mesh.valence(gone) - 4 < 3 || !linkCondition(mesh, keep, gone) ||
    !keepsNormals(mesh, x, keep, gone, m, settings));
}

bool collapseInPass(SurfaceMesh& mesh, const std::vector<Vec3>& x, int keep, int gone,
  const Vec3& m, const CollapseSettings& settings, std::vector<char>& touched, CrossingGuard& guard)
{
  if (touched[keep] || touched[gone] || !collapseIsOk(mesh, x, keep, gone, m, settings))
  {
    return false;
  }
  std::vector<std::array<int, 2>> rim; // of the fan (m, u, w) the merge makes
  if (settings.avoidCrossings)
  {
    forEachFanTriangle(mesh, keep, gone, [&](int, int u, int w) { rim.push_back({ u, w }); });
    if (guard.collapseCrosses(keep, gone, m, rim))
    {
      return false;
    }
  }
  for (int v : { keep, gone })
  {
    touched[v] = 1;
    for (int q = mesh.ringBegin(v); q < mesh.ringEnd(v); ++q)
    {
      touched[mesh.ring(q)] = 1;
    }
  }
  if (!mesh.collapse(keep, gone, m))
  {
    return false;
  }
  if (settings.avoidCrossings)
  {
    guard.addCollapse(keep, gone, m, rim);
  }
  return true;
}

int collapseEdges(SurfaceMesh& mesh, const CollapseSettings& settings)
{
  // Decisions read the surface as it was before the pass (the rings stay so until the commit).
  const std::vector<Vec3> x = mesh.points();
  const std::vector<std::array<int, 3>> triangles = mesh.triangles();
  const std::vector<double> anchors = mesh.vertexValues<double>(kAnchor); // before the pass
  const int nv = mesh.vertexCount();
  std::vector<char> touched(nv, 0);
  CrossingGuard guard(x, triangles, settings.guardOnlyIn);
  int collapses = 0;
  auto collapse = [&](int keep, int gone, const Vec3& m) {
    collapses += collapseInPass(mesh, x, keep, gone, m, settings, touched, guard);
  };
  for (const auto& t : triangles)
  {
    if (nv - collapses <= 4 || !smallestAngleBelow(x[t[0]], x[t[1]], x[t[2]], settings.maxAngle))
    {
      continue;
    }
    // The shortest edge (a, b), merged at its midpoint; but a vertex of valence 3 beside it (which
    // would be left with two triangles) goes first, into a, where it leaves one triangle. Anchored
    // ends keep their places (mergeOf).
    int a = t[0], b = t[1];
    for (int e = 1; e < 3; ++e)
    {
      const int u = t[e], w = t[(e + 1) % 3];
      if ((x[u] - x[w]).squaredNorm() < (x[a] - x[b]).squaredNorm())
      {
        a = u;
        b = w;
      }
    }
    const int p = mesh.ringEntry(a, b);
    const int c = mesh.ring(mesh.next(a, p)), d = mesh.ring(mesh.previous(a, p));
    const int lone = mesh.valence(c) == 3 ? c : (mesh.valence(d) == 3 ? d : -1);
    if (lone >= 0)
    {
      // into a where it stands, unless the lone vertex holds more of a rim (kAnchor): the kept
      // vertex stays where it is
      const Merge merge = mergeOf(x, anchors, a, lone);
      collapse(merge.keep, merge.gone, x[merge.keep]);
    }
    else
    {
      const Merge merge = mergeOf(x, anchors, a, b);
      collapse(merge.keep, merge.gone, merge.at);
    }
  }
  return collapses > 0 && mesh.commit() ? collapses : 0;
}

} // namespace shrinkwrap
