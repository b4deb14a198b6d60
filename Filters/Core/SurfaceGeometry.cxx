#include "SurfaceGeometry.h"

#include <vtkSMPTools.h>

#include <cmath>

namespace shrinkwrap
{

namespace
{
double angle(const Vec3& u, const Vec3& v)
{
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

double cotangent(const Vec3& u, const Vec3& v)
{
  const double s = u.cross(v).norm();
  return s > 0 ? u.dot(v) / s : 0.0; // a degenerate angle contributes nothing; the step reports it
}
} // namespace

std::array<double, 3> triangleAngles(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return { angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c) };
}

void computeGeometry(const SurfaceMesh& mesh, const std::vector<Vec3>& x, SurfaceGeometry& g)
{
  const int nt = mesh.triangleCount(), nv = mesh.vertexCount();
  const auto& tris = mesh.triangles();
  g.triangleArea.resize(nt);
  g.coVolume.assign(nv, 0.0);
  g.normal.resize(nv);
  g.weight.resize(mesh.ringEnd(nv - 1));
  g.curvature.resize(nv);
  for (int t = 0; t < nt; ++t)
  {
    const auto& v = tris[t];
    g.triangleArea[t] = 0.5 * (x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]).norm();
  }
  vtkSMPTools::For(0, nv, [&](int b, int e) {
    for (int i = b; i < e; ++i)
    {
      double coVolume = 0;
      Vec3 normal = Vec3::Zero(), laplacian = Vec3::Zero();
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const int j = mesh.ring(p), k = mesh.ring(mesh.next(i, p)), l = mesh.ring(mesh.previous(i, p));
        coVolume += g.triangleArea[mesh.ringTriangle(p)] / 3.0;
        // Triangle (i, j, k): its normal weighted by its angle at i.
        const Vec3 n = (x[j] - x[i]).cross(x[k] - x[i]);
        const double len = n.norm();
        if (len > 0)
        {
          normal += angle(x[j] - x[i], x[k] - x[i]) * n / len;
        }
        // Edge (i, j): opposite corners k (triangle i, j, k) and l (triangle i, l, j).
        const double w = 0.5 * (cotangent(x[i] - x[k], x[j] - x[k]) + cotangent(x[i] - x[l], x[j] - x[l]));
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
    return angle(b - a, c - a); // opposite bc, at a
  }
  return ca <= ab ? angle(c - b, a - b) : angle(a - c, b - c);
}

SmallestAngle smallestAngle(const SurfaceMesh& mesh, const std::vector<Vec3>& x)
{
  const auto& tris = mesh.triangles();
  std::vector<SmallestAngle> parts(std::max(1, mesh.triangleCount() / 4096 + 1));
  const int n = mesh.triangleCount(), chunk = (n + static_cast<int>(parts.size()) - 1) / static_cast<int>(parts.size());
  vtkSMPTools::For(0, static_cast<int>(parts.size()), [&](int b, int e) {
    for (int p = b; p < e; ++p)
    {
      for (int t = p * chunk; t < std::min(n, (p + 1) * chunk); ++t)
      {
        const auto& v = tris[t];
        const double m = smallestAngle(x[v[0]], x[v[1]], x[v[2]]);
        if (!(m >= parts[p].angle)) // NaN counts as smallest
        {
          parts[p] = { m, t };
        }
      }
    }
  });
  SmallestAngle result;
  for (const SmallestAngle& part : parts)
  {
    if (part.triangle >= 0 && !(part.angle >= result.angle))
    {
      result = part;
    }
  }
  return result;
}

} // namespace shrinkwrap
