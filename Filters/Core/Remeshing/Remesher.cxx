#include "Remeshing/Remesher.h"

#include "Remeshing/EdgeSplits.h"
#include "Remeshing/Relaxation.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

namespace shrinkwrap
{

namespace
{
// The size of edge (a, b) in units of the uniform one: the mean of its ends' (1 without sizes).
double edgeSize(const std::vector<double>& sizes, int a, int b)
{
  return sizes.empty() ? 1.0 : 0.5 * (sizes[a] + sizes[b]);
}
} // namespace

void assignEdgeSizes(SurfaceMesh& mesh, const RemeshSettings& settings)
{
  const std::vector<Vec3>& x = mesh.points();
  SurfaceGeometry g;
  computeGeometry(mesh, x, g);
  const double L = settings.targetLength, e = settings.chordError * L;
  std::vector<double>& sizes = mesh.addVertexProperty<double>(kEdgeSize, 0).values();
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    double curvature = 0;
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      const Vec3 d = x[mesh.ring(p)] - x[i];
      const double d2 = d.squaredNorm();
      curvature = d2 > 0 ? std::max(curvature, 2 * std::abs(g.normal[i].dot(d)) / d2) : curvature;
    }
    const double square =
      curvature > 0 ? 6 * e / curvature - 3 * e * e : std::numeric_limits<double>::infinity();
    const double length = square > 0 ? std::sqrt(square) : 0;
    sizes[i] = std::clamp(length / L, settings.shortest, settings.longest);
  }
  // Sizes that jump between neighbours make poor triangles: each may exceed a neighbour's by at
  // most `grading` times the edge between them (in L); three sweeps carry that about three rings
  // out.
  for (int pass = 0; pass < 3; ++pass)
  {
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const int j = mesh.ring(p);
        sizes[i] = std::min(sizes[i], sizes[j] + settings.grading * (x[j] - x[i]).norm() / L);
      }
    }
  }
}

int splitLongEdges(SurfaceMesh& mesh, double maxLength, const std::function<bool()>& stop)
{
  int splits = 0;
  // After the first pass only the edges at the new vertices (numbered after the others) can be
  // long.
  for (int pass = 0, firstNew = 0; pass < 16 && !(stop && stop()); ++pass)
  {
    std::vector<std::array<int, 2>> longEdges;
    const std::vector<double> sizes = mesh.vertexValues<double>(kEdgeSize); // none: uniform
    const std::vector<Vec3>& x = mesh.points();
    for (const auto& e : edgesOf(mesh))
    {
      if (std::max(e[0], e[1]) >= firstNew &&
        (x[e[0]] - x[e[1]]).norm() > maxLength * edgeSize(sizes, e[0], e[1]))
      {
        longEdges.push_back(e);
      }
    }
    firstNew = mesh.vertexCount();
    const int made = longEdges.empty() ? 0 : splitEdges(mesh, longEdges, stop);
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
// No edge from the merged vertex (which keeps the kept vertex's size) to a neighbour of either end
// longer than maxLength.
bool staysShort(const SurfaceMesh& mesh, const std::vector<Vec3>& x,
  const std::vector<double>& sizes, const Merge& merge, double maxLength)
{
  for (int v : { merge.keep, merge.gone })
  {
    for (int p = mesh.ringBegin(v); p < mesh.ringEnd(v); ++p)
    {
      if ((x[mesh.ring(p)] - merge.at).norm() >
        maxLength * edgeSize(sizes, merge.keep, mesh.ring(p)))
      {
        return false;
      }
    }
  }
  return true;
}

// One pass over the edges with an end in `look` (all when it is empty), in the order of edgesOf.
// `look` becomes, numbered as after the pass, the ends of the short edges it found: the only edges
// that can be short in the next pass are those and the ones a merge moved an end of (the kept
// vertex is among them), since no other vertex moves. So later passes look at a few edges and
// decide as a pass over all of them would.
int collapsePass(SurfaceMesh& mesh, double minLength, double maxLength,
  const CollapseSettings& settings, std::vector<char>& look, StopPoll& stopped)
{
  const std::vector<Vec3> x = mesh.points(); // as the rings are: before the pass
  const std::vector<std::array<int, 3>> triangles = mesh.triangles(); // edits change the mesh's own
  CrossingGuard guard(x, triangles, settings.guardOnlyIn);
  guard.setStop([&] { return stopped.now(); });
  const int nv = mesh.vertexCount();
  std::vector<char> touched(nv, 0), shortEnd(nv, 0), gone(nv, 0);
  int collapses = 0;
  // as the pass began
  const std::vector<double> sizes = mesh.vertexValues<double>(kEdgeSize);
  const std::vector<double> anchors = mesh.vertexValues<double>(kAnchor);
  for (int a = 0; a < nv && !stopped(); ++a)
  {
    for (int p = mesh.ringBegin(a); p < mesh.ringEnd(a); ++p)
    {
      const int b = mesh.ring(p);
      if (a > b || !(look.empty() || look[a] || look[b]) ||
        !((x[a] - x[b]).norm() < minLength * edgeSize(sizes, a, b)))
      {
        continue;
      }
      shortEnd[a] = shortEnd[b] = 1;
      if (touched[a] || touched[b] || nv - collapses <= 4) // collapseInPass refuses touched ends
      {
        continue;
      }
      const Merge merge = mergeOf(x, anchors, a, b);
      if (staysShort(mesh, x, sizes, merge, maxLength) &&
        collapseInPass(mesh, x, merge.keep, merge.gone, merge.at, settings, touched, guard))
      {
        gone[merge.gone] = 1;
        ++collapses;
      }
    }
  }
  look.assign(nv - collapses, 0);
  for (int v = 0, kept = 0; v < nv; ++v)
  {
    if (!gone[v])
    {
      look[kept++] = shortEnd[v];
    }
  }
  return collapses > 0 && mesh.commit() ? collapses : 0;
}
} // namespace

int collapseShortEdges(SurfaceMesh& mesh, double minLength, double maxLength,
  const CollapseSettings& settings, const std::function<bool()>& stop)
{
  int collapses = 0;
  std::vector<char> look; // every edge in the first pass
  StopPoll stopped(stop);
  for (int pass = 0; pass < 16 && !stopped(); ++pass)
  {
    const int made = collapsePass(mesh, minLength, maxLength, settings, look, stopped);
    collapses += made;
    if (made == 0)
    {
      break;
    }
  }
  return collapses;
}

int equalizeValences(
  SurfaceMesh& mesh, const FlipSettings& settings, const std::function<bool()>& stop)
{
  auto deviation = [](int a, int b, int c, int d) {
    return std::abs(a - 6) + std::abs(b - 6) + std::abs(c - 6) + std::abs(d - 6);
  };
  FlipPass pass(mesh, settings);
  StopPoll stopped(stop);
  pass.setStop([&] { return stopped.now(); });
  for (const auto& e : edgesOf(mesh))
  {
    if (stopped())
    {
      break;
    }
    const int i = e[0], j = e[1];
    const int p = mesh.ringEntry(i, j);
    const int c = mesh.ring(mesh.next(i, p)), d = mesh.ring(mesh.previous(i, p));
    if (!pass.free(mesh, i, j, c, d))
    {
      continue;
    }
    const int vi = mesh.valence(i), vj = mesh.valence(j), vc = mesh.valence(c),
              vd = mesh.valence(d);
    // A flip that the angle pass (flipEdges, after each step's edits) would flip back is churn.
    if (deviation(vi - 1, vj - 1, vc + 1, vd + 1) < deviation(vi, vj, vc, vd) &&
      mesh.ringEntry(c, d) < 0 && !flipGainsAngle(pass.points(), c, d, i, j, settings.minGain))
    {
      pass.flip(mesh, i, j, c, d);
    }
  }
  return pass.flips() > 0 && mesh.commit() ? pass.flips() : 0;
}

RemeshReport remesh(SurfaceMesh& mesh, const RemeshSettings& settings)
{
  RemeshReport report;
  const double L = settings.targetLength;
  if (!(L > 0) || !std::isfinite(L) || !(settings.collapseBelow < settings.splitAbove))
  {
    report.status =
      Status::failure("the target edge length must be positive, and collapseBelow < splitAbove");
    return report;
  }
  RelaxSettings relax;
  relax.iterations = settings.relaxWeight > 0 ? 1 : 0;
  relax.weight = settings.relaxWeight;
  relax.flips = settings.flips;
  const auto stopped = [&] { return settings.stop && settings.stop(); };
  for (int k = 0; k < settings.iterations && !stopped(); ++k)
  {
    if (settings.adaptive())
    {
      assignEdgeSizes(mesh, settings);
    }
    report.splits += splitLongEdges(mesh, settings.splitAbove * L, settings.stop);
    if (stopped())
      break;
    report.collapses += collapseShortEdges(
      mesh, settings.collapseBelow * L, settings.splitAbove * L, settings.collapses, settings.stop);
    if (stopped())
      break;
    report.flips += equalizeValences(mesh, settings.flips, settings.stop);
    if (stopped())
      break;
    relaxTangentially(mesh, relax, settings.stop);
  }
  mesh.removeVertexProperty(kEdgeSize);
  return report;
}

} // namespace shrinkwrap
