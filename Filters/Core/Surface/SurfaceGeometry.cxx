#include "Surface/SurfaceGeometry.h"
#include "Common/Parallel.h"

#include <cmath>

namespace shrinkwrap
{

std::array<double, 3> triangleAngles(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return { angleBetween(b - a, c - a), angleBetween(c - b, a - b), angleBetween(a - c, b - c) };
}

namespace
{
// Per triangle, computed once and gathered by the vertices: unit normal, and per corner the angle
// and the cotangent.
struct TriangleTerms
{
  Vec3 normal;
  std::array<double, 3> angle, cotangent;
};

int cornerOf(const std::array<int, 3>& triangle, int vertex)
{
  return triangle[0] == vertex ? 0 : (triangle[1] == vertex ? 1 : 2);
}
} // namespace

void computeGeometry(const SurfaceMesh& mesh, const std::vector<Vec3>& x, SurfaceGeometry& g)
{
  const int nt = mesh.triangleCount(), nv = mesh.vertexCount();
  const auto& tris = mesh.triangles();
  g.triangleArea.resize(nt);
  g.coVolume.assign(nv, 0.0);
  g.normal.resize(nv);
  g.weight.resize(mesh.ringEnd(nv - 1));
  g.curvature.resize(nv);
  std::vector<TriangleTerms> terms(nt);
  parallelFor(0, nt, kCheapGrain, [&](int b, int e) {
    for (int t = b; t < e; ++t)
    {
      const auto& v = tris[t];
      const Vec3 n = (x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]);
      const double len = n.norm();
      g.triangleArea[t] = 0.5 * len;
      terms[t].normal = len > 0 ? Vec3(n / len) : Vec3::Zero();
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 u = x[v[(k + 1) % 3]] - x[v[k]], w = x[v[(k + 2) % 3]] - x[v[k]];
        // angleBetween and cotangent from one sine and cosine (times |u| |w|)
        const double sine = u.cross(w).norm(), cosine = u.dot(w);
        terms[t].angle[k] = std::atan2(sine, cosine);
        terms[t].cotangent[k] =
          sine > 0 ? cosine / sine : 0.0; // degenerate: nothing (the step reports it)
      }
    }
  });
  parallelFor(0, nv, kCheapGrain, [&](int b, int e) {
    for (int i = b; i < e; ++i)
    {
      double coVolume = 0;
      Vec3 normal = Vec3::Zero(), laplacian = Vec3::Zero();
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const int j = mesh.ring(p), t = mesh.ringTriangle(p),
                  s = mesh.ringTriangle(mesh.previous(i, p));
        coVolume += g.triangleArea[t] / 3.0;
        // Triangle (i, j, k): its normal weighted by its angle at i.
        normal += terms[t].angle[cornerOf(tris[t], i)] * terms[t].normal;
        // Edge (i, j): the corners opposite it in triangles (i, j, k) and (i, l, j), i.e. after j.
        const int k = mesh.ring(mesh.next(i, p)), l = mesh.ring(mesh.previous(i, p));
        const double w = 0.5 *
          (terms[t].cotangent[cornerOf(tris[t], k)] + terms[s].cotangent[cornerOf(tris[s], l)]);
        g.weight[p] = w;
        laplacian += w * (x[j] - x[i]);
      }
      g.coVolume[i] = coVolume;
      const double len = normal.norm();
      g.normal[i] = len > 0 ? Vec3(normal / len) : Vec3::Zero();
      g.curvature[i] = coVolume > 0 ? Vec3(laplacian / coVolume) : Vec3::Zero();
    }
  });
  g.area = 0;
  for (int t = 0; t < nt; ++t)
  {
    g.area += g.triangleArea[t];
  }
}

double smallestAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc <= ab && bc <= ca)
  {
    return angleBetween(b - a, c - a); // opposite bc, at a
  }
  return ca <= ab ? angleBetween(c - b, a - b) : angleBetween(a - c, b - c);
}

namespace
{
// The sine of the smallest angle (opposite the shortest edge, so at most 60 degrees, where the sine
// grows with the angle): ranks triangles without an atan2 each.
double smallestSine(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  const double twiceArea = (b - a).cross(c - a).norm();
  const double adjacent = bc <= ab && bc <= ca ? ab * ca : (ca <= ab ? ab * bc : bc * ca);
  return adjacent > 0 ? twiceArea / std::sqrt(adjacent) : 0.0;
}
} // namespace

bool smallestAngleBelow(const Vec3& a, const Vec3& b, const Vec3& c, double angle)
{
  // The smallest angle is at most 60 degrees, where the sine grows with the angle; a sine clearly
  // above the bound's (beyond both computations' rounding) is an angle above it.
  if (angle > 0 && angle <= M_PI / 3 && smallestSine(a, b, c) >= std::sin(angle) * (1 + 1e-9))
  {
    return false;
  }
  return smallestAngle(a, b, c) < angle;
}

SmallestAngle smallestAngle(const SurfaceMesh& mesh, const std::vector<Vec3>& x)
{
  const auto& tris = mesh.triangles();
  struct Part
  {
    double sine = 2;
    int triangle = -1;
  };
  std::vector<Part> parts(std::max(1, mesh.triangleCount() / static_cast<int>(kCheapGrain) + 1));
  const int n = mesh.triangleCount(),
            chunk = (n + static_cast<int>(parts.size()) - 1) / static_cast<int>(parts.size());
  parallelFor(0, static_cast<int>(parts.size()), 1, [&](int b, int e) {
    for (int p = b; p < e; ++p)
    {
      for (int t = p * chunk; t < std::min(n, (p + 1) * chunk); ++t)
      {
        const auto& v = tris[t];
        const double m = smallestSine(x[v[0]], x[v[1]], x[v[2]]);
        if (!(m >= parts[p].sine)) // NaN counts as smallest
        {
          parts[p] = { m, t };
        }
      }
    }
  });
  SmallestAngle result;
  double sine = 2;
  for (const Part& part : parts)
  {
    if (part.triangle >= 0 && !(part.sine >= sine))
    {
      sine = part.sine;
      const auto& v = tris[part.triangle];
      result = { smallestAngle(x[v[0]], x[v[1]], x[v[2]]), part.triangle };
    }
  }
  return result;
}

double enclosedVolume(const SurfaceMesh& mesh, const std::vector<Vec3>& x)
{
  double volume = 0;
  for (const auto& t : mesh.triangles())
  {
    volume += tripleProduct(x[t[0]], x[t[1]], x[t[2]]);
  }
  return volume / 6.0;
}

} // namespace shrinkwrap
