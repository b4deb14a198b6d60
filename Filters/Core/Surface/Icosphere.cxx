#include "Surface/Icosphere.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace shrinkwrap
{

long long icosphereVertexCount(int level)
{
  // N_V^s = (N_E^0 (4^s - 1) + 3 N_V^0) / 3 with N_V^0 = 12, N_E^0 = 30.
  const long long p = 1LL << (2 * level);
  return (30 * (p - 1) + 36) / 3;
}

TriangleSoup icosphere(int level, const Vec3& center, double radius)
{
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },
    { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 },
    { -g, 0, 1 } };
  for (Vec3& p : unit)
  {
    p.normalize();
  }
  std::vector<std::array<int, 3>> triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 },
    { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 },
    { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 },
    { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };
  for (int s = 0; s < level; ++s)
  {
    std::unordered_map<std::uint64_t, int> midpoints;
    auto midpoint = [&](int a, int b) {
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end())
      {
        return it->second;
      }
      unit.push_back((unit[a] + unit[b]).normalized());
      return midpoints[key] = static_cast<int>(unit.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    finer.reserve(4 * triangles.size());
    for (const auto& t : triangles)
    {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({ t[0], ab, ca });
      finer.push_back({ t[1], bc, ab });
      finer.push_back({ t[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    triangles.swap(finer);
  }
  TriangleSoup surface;
  surface.triangles = std::move(triangles);
  surface.points.reserve(unit.size());
  for (const Vec3& p : unit)
  {
    surface.points.push_back(center + radius * p);
  }
  return surface;
}

} // namespace shrinkwrap
