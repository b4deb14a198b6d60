#include "Remesher.h"

#include "EdgeSplits.h"
#include "Relaxation.h"
#include "SelfIntersections.h"

#include <cmath>
#include <cstdlib>

namespace shrinkwrap
{

int splitLongEdges(SurfaceMesh& mesh, double maxLength)
{
  int splits = 0;
  for (int pass = 0; pass < 16; ++pass)
  {
    std::vector<std::array<int, 2>> longEdges;
    for (const auto& e : edgesOf(mesh))
    {
      if ((mesh.points()[e[0]] - mesh.points()[e[1]]).norm() > maxLength)
      {
        longEdges.push_back(e);
      }
    }
    const int made = longEdges.empty() ? 0 : splitEdges(mesh, longEdges);
    splits += made;
    if (made == 0)
    {
      break;
    }
  }
  return splits;
}

namespace
{
// No edge from the merged vertex at m to a neighbour of a or b longer than maxLength.
bool staysShort(const SurfaceMesh& mesh, const std::vector<Vec3>& x, int a, int b, const Vec3& m, double maxLength)
{
  for (int v : { a, b })
  {
    for (int p = mesh.ringBegin(v); p < mesh.ringEnd(v); ++p)
    {
      if ((x[mesh.ring(p)] - m).norm() > maxLength)
      {
        return false;
      }
    }
  }
  return true;
}

int collapsePass(SurfaceMesh& mesh, double minLength, double maxLength, const CollapseSettings& settings)
{
  const std::vector<Vec3> x = mesh.points(); // as the rings are: before the pass
  const std::vector<std::array<int, 3>> triangles = mesh.triangles(); // edits change the mesh's own
  CrossingGuard guard(x, triangles, settings.guardOnlyIn);
  std::vector<char> touched(mesh.vertexCount(), 0);
  int collapses = 0;
  for (const auto& e : edgesOf(mesh))
  {
    const int a = e[0], b = e[1];
    const Vec3 m = 0.5 * (x[a] + x[b]);
    if (mesh.vertexCount() - collapses > 4 && (x[a] - x[b]).norm() < minLength &&
      staysShort(mesh, x, a, b, m, maxLength))
    {
      collapses += collapseInPass(mesh, x, a, b, m, settings, touched, guard);
    }
  }
  return collapses > 0 && mesh.commit() ? collapses : 0;
}
} // namespace

int collapseShortEdges(SurfaceMesh& mesh, double minLength, double maxLength, const CollapseSettings& settings)
{
  int collapses = 0;
  for (int pass = 0; pass < 16; ++pass)
  {
    const int made = collapsePass(mesh, minLength, maxLength, settings);
    collapses += made;
    if (made == 0)
    {
      break;
    }
  }
  return collapses;
}

int equalizeValences(SurfaceMesh& mesh, const FlipSettings& settings)
{
  const std::vector<Vec3>& x = mesh.points();
  const double cosMax = std::cos(settings.maxDihedral * M_PI / 180.0);
  const std::vector<std::array<int, 3>> triangles = mesh.triangles(); // flips change the mesh's own
  CrossingGuard guard(x, triangles, settings.guardOnlyIn);
  std::vector<char> touched(mesh.vertexCount(), 0);
  auto deviation = [](int a, int b, int c, int d) {
    return std::abs(a - 6) + std::abs(b - 6) + std::abs(c - 6) + std::abs(d - 6);
  };
  int flips = 0;
  for (const auto& e : edgesOf(mesh))
  {
    const int i = e[0], j = e[1];
    const int p = mesh.ringEntry(i, j);
    const int c = mesh.ring(mesh.next(i, p)), d = mesh.ring(mesh.previous(i, p));
    if (touched[i] || touched[j] || touched[c] || touched[d] || mesh.valence(i) <= 3 || mesh.valence(j) <= 3 ||
      c == d || mesh.ringEntry(c, d) >= 0)
    {
      continue;
    }
    const int vi = mesh.valence(i), vj = mesh.valence(j), vc = mesh.valence(c), vd = mesh.valence(d);
    if (deviation(vi - 1, vj - 1, vc + 1, vd + 1) >= deviation(vi, vj, vc, vd) ||
      !flipKeepsShape(x, i, j, c, d, cosMax) || (settings.avoidCrossings && guard.flipCrosses(i, j, c, d)) ||
      !mesh.flip(i, j))
    {
      continue;
    }
    touched[i] = touched[j] = touched[c] = touched[d] = 1;
    ++flips;
    if (settings.avoidCrossings)
    {
      guard.addFlip(i, j, c, d);
    }
  }
  return flips > 0 && mesh.commit() ? flips : 0;
}

RemeshReport remesh(SurfaceMesh& mesh, const RemeshSettings& settings)
{
  RemeshReport report;
  const double L = settings.targetLength;
  if (!(L > 0) || !std::isfinite(L) || !(settings.collapseBelow < settings.splitAbove))
  {
    report.status = Status::failure("the target edge length must be positive, and collapseBelow < splitAbove");
    return report;
  }
  RelaxSettings relax;
  relax.iterations = settings.relaxWeight > 0 ? 1 : 0;
  relax.weight = settings.relaxWeight;
  relax.flips = settings.flips;
  for (int k = 0; k < settings.iterations; ++k)
  {
    report.splits += splitLongEdges(mesh, settings.splitAbove * L);
    report.collapses += collapseShortEdges(
      mesh, settings.collapseBelow * L, settings.splitAbove * L, settings.collapses);
    report.flips += equalizeValences(mesh, settings.flips);
    relaxTangentially(mesh, relax);
  }
  return report;
}

} // namespace shrinkwrap
