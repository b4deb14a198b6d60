#include "Evolution/RimCoverage.h"

#include "Common/Parallel.h"
#include "Distance/TriangleDistance.h"
#include "Surface/TriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

std::vector<Vec3> rimSamples(const std::vector<std::array<Vec3, 2>>& rims, double spacing)
{
  std::vector<Vec3> samples;
  if (!(spacing > 0))
  {
    return samples;
  }
  for (const auto& [a, b] : rims)
  {
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int k = 0; k <= pieces; ++k)
    {
      samples.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
    }
  }
  // Every rim vertex ends two edges: once is enough.
  auto less = [](const Vec3& p, const Vec3& q) {
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  };
  std::sort(samples.begin(), samples.end(), less);
  samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
  return samples;
}

namespace
{
struct Nearest
{
  int triangle = -1; // -1: none within reach
  double squaredDistance = 0;
  Vec3 point = Vec3::Zero();
  Feature feature = Feature::Face;
};

Vec3 faceNormal(const std::vector<Vec3>& y, const std::array<int, 3>& t)
{
  return (y[t[1]] - y[t[0]]).cross(y[t[2]] - y[t[0]]);
}

// The pseudonormal that tells the sides of a point whose nearest surface point lies on this feature
// (Baerentzen & Aanaes, as PseudoNormals.h, which serves a fixed soup; this surface changes every
// step and only a few features are asked): the face's, the sum of the two at an edge, or the
// angle-weighted sum at a vertex.
Vec3 featureNormal(
  const SurfaceMesh& mesh, const std::vector<Vec3>& y, int triangle, Feature feature)
{
  const auto& t = mesh.triangles()[triangle];
  switch (feature)
  {
    case Feature::Vertex0:
    case Feature::Vertex1:
    case Feature::Vertex2:
    {
      const int v = t[static_cast<int>(feature) - static_cast<int>(Feature::Vertex0)];
      Vec3 n =
        Vec3::Zero(); // angle-weighted, as PseudoNormals.h: then the side of a point is right
      for (int p = mesh.ringBegin(v); p < mesh.ringEnd(v); ++p)
      {
        const Vec3 u = y[mesh.ring(p)] - y[v], w = y[mesh.ring(mesh.next(v, p))] - y[v];
        n +=
          angleBetween(u, w) * faceNormal(y, mesh.triangles()[mesh.ringTriangle(p)]).normalized();
      }
      return n;
    }
    case Feature::Edge01:
    case Feature::Edge12:
    case Feature::Edge20:
    {
      const int slot = static_cast<int>(feature) - static_cast<int>(Feature::Edge01);
      const int a = t[slot], p = mesh.ringEntry(a, t[(slot + 1) % 3]);
      if (p < 0)
      {
        return faceNormal(y, t);
      }
      // the triangles on both sides of the edge: (a, b, next) and (a, previous, b)
      return faceNormal(y, mesh.triangles()[mesh.ringTriangle(p)]).normalized() +
        faceNormal(y, mesh.triangles()[mesh.ringTriangle(mesh.previous(a, p))]).normalized();
    }
    default:
      return faceNormal(y, t);
  }
}

// Barycentric coordinates of x (in the triangle's plane) in triangle (a, b, c).
std::array<double, 3> barycentric(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 e0 = b - a, e1 = c - a, r = x - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = r.dot(e0),
               d21 = r.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 0))
  {
    return { 1.0 / 3, 1.0 / 3, 1.0 / 3 };
  }
  const double v = std::clamp((d11 * d20 - d01 * d21) / det, 0.0, 1.0);
  const double w = std::clamp((d00 * d21 - d01 * d20) / det, 0.0, 1.0 - v);
  return { 1 - v - w, v, w };
}

// Per sample, the nearest point of the surface within `reach`, looked for first within `near`.
std::vector<Nearest> nearestPoints(
  const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double near, double reach)
{
  const std::vector<Vec3>& y = mesh.points();
  // A grid of the triangles (rebuilt every step, by counting sort) rather than a tree: the searches
  // reach only a few edge lengths, and building a tree every step cost more than they do.
  const auto& triangles = mesh.triangles();
  const TriangleGrid grid(y, triangles);
  std::vector<Nearest> hits(samples.size());
  parallelFor(0, static_cast<Index>(samples.size()), [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      const Vec3& p = samples[i];
      Nearest& hit = hits[i];
      auto search = [&](double radius) {
        hit.squaredDistance = radius * radius;
        Box near;
        near.min = p - Vec3::Constant(radius);
        near.max = p + Vec3::Constant(radius);
        grid.forEachNear(near, [&](int t) {
          const auto& c = triangles[t];
          const TrianglePoint q = closestPointOnTriangle(p, y[c[0]], y[c[1]], y[c[2]]);
          const double d2 = (q.point - p).squaredNorm();
          if (d2 < hit.squaredDistance || (d2 == hit.squaredDistance && t < hit.triangle))
          {
            hit = { t, d2, q.point, q.feature };
          }
        });
      };
      // Most samples lie on the surface: a small box finds them (a hit within it is the nearest);
      // the rest mostly within a third of the reach, whose box holds a ninth of the triangles.
      double searched = 0;
      for (const double radius : { std::min(near, reach), reach / 3, reach })
      {
        if (radius > searched)
        {
          search(radius);
          searched = radius;
        }
        if (hit.triangle >= 0)
        {
          break;
        }
      }
    }
  });
  return hits;
}
} // namespace

std::vector<Vec3> rimMoves(
  const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double tolerance, double reach)
{
  const std::vector<Vec3>& y = mesh.points();
  std::vector<Vec3> moves(y.size(), Vec3::Zero());
  if (samples.empty() || mesh.triangleCount() == 0)
  {
    return moves;
  }
  const std::vector<Nearest> hits = nearestPoints(mesh, samples, 4 * tolerance, reach);
  // Serial from here, in sample order: the same moves on every run (cached steps equal fresh ones).
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const Nearest& hit = hits[i];
    const Vec3 gap = samples[i] - hit.point;
    if (hit.triangle < 0 || !(hit.squaredDistance > tolerance * tolerance) ||
      !(gap.dot(featureNormal(mesh, y, hit.triangle, hit.feature)) > 0))
    {
      continue;
    }
    const auto& t = mesh.triangles()[hit.triangle];
    const auto w = barycentric(hit.point, y[t[0]], y[t[1]], y[t[2]]);
    const double sum =
      w[0] * w[0] + w[1] * w[1] + w[2] * w[2]; // moves w_k gap / sum carry the point by gap
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 move = gap * (w[k] / sum);
      if (move.squaredNorm() > moves[t[k]].squaredNorm())
      {
        moves[t[k]] = move;
      }
    }
  }
  return moves;
}

std::vector<double> rimHolds(
  const SurfaceMesh& mesh, const std::vector<Vec3>& samples, double reach)
{
  const std::vector<Vec3>& y = mesh.points();
  std::vector<double> holds(y.size(), 0.0);
  if (samples.empty() || mesh.triangleCount() == 0)
  {
    return holds;
  }
  // Most samples lie within a fraction of an edge of the surface: searched there first, the same
  // nearest points for a few grid cells each instead of the whole reach's.
  constexpr double kNearFirst = 0.25;
  for (const Nearest& hit : nearestPoints(mesh, samples, kNearFirst * reach, reach))
  {
    if (hit.triangle >= 0)
    {
      const auto& t = mesh.triangles()[hit.triangle];
      const auto w = barycentric(hit.point, y[t[0]], y[t[1]], y[t[2]]);
      for (int k = 0; k < 3; ++k)
      {
        holds[t[k]] = std::max(holds[t[k]], w[k]);
      }
    }
  }
  return holds;
}

} // namespace shrinkwrap
