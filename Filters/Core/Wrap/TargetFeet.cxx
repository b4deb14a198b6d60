#include "Wrap/TargetFeet.h"

#include "Common/Parallel.h"

#include <algorithm>

namespace shrinkwrap
{

std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 1e-14 * std::max(d00 * d11, 1e-300)))
  {
    const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    if (da <= db && da <= dc)
    {
      return { 1, 0, 0 };
    }
    return db <= dc ? std::array<double, 3>{ 0, 1, 0 } : std::array<double, 3>{ 0, 0, 1 };
  }
  double v = (d11 * d20 - d01 * d21) / det;
  double w = (d00 * d21 - d01 * d20) / det;
  v = std::clamp(v, 0.0, 1.0);
  w = std::clamp(w, 0.0, 1.0);
  if (v + w > 1)
  {
    const double sum = v + w;
    v /= sum;
    w /= sum;
  }
  return { 1 - v - w, v, w };
}

TargetFeet feetOnTriangles(
  const std::vector<Vec3>& x, const TriangleSoup& soup, const NearestOnSoup& nearest)
{
  TargetFeet feet;
  const std::size_t n = x.size();
  feet.element.assign(n, -1);
  feet.begin.resize(n + 1);
  feet.points.assign(3 * n, 0);
  feet.weights.assign(3 * n, 0.0);
  parallelFor(0, static_cast<Index>(n), kQueryGrain, [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      const auto [triangle, point] = nearest(x[i]);
      feet.begin[i] = 3 * i;
      if (triangle < 0)
      {
        continue;
      }
      const auto& t = soup.triangles[triangle];
      const std::array<double, 3> w =
        barycentric(point, soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]);
      feet.element[i] = triangle;
      for (int k = 0; k < 3; ++k)
      {
        feet.points[3 * i + k] = t[k];
        feet.weights[3 * i + k] = w[k];
      }
    }
  });
  feet.begin[n] = static_cast<std::int64_t>(3 * n);
  return feet;
}

TargetFeet feetOnPoints(const std::vector<Vec3>& x, const PointSurface& surface)
{
  const std::size_t n = x.size();
  std::vector<std::vector<int>> ids(n);
  std::vector<std::vector<double>> weights(n);
  parallelFor(0, static_cast<Index>(n), kQueryGrain, [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      surface.fitWeights(x[i], ids[i], weights[i]);
    }
  });
  TargetFeet feet;
  feet.element.assign(n, -1);
  feet.begin.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    feet.begin[i + 1] = feet.begin[i] + static_cast<std::int64_t>(ids[i].size());
    if (!ids[i].empty())
    {
      const auto heaviest = std::max_element(weights[i].begin(), weights[i].end());
      feet.element[i] = ids[i][heaviest - weights[i].begin()];
    }
  }
  feet.points.reserve(feet.begin[n]);
  feet.weights.reserve(feet.begin[n]);
  for (std::size_t i = 0; i < n; ++i)
  {
    feet.points.insert(feet.points.end(), ids[i].begin(), ids[i].end());
    feet.weights.insert(feet.weights.end(), weights[i].begin(), weights[i].end());
  }
  return feet;
}

} // namespace shrinkwrap
