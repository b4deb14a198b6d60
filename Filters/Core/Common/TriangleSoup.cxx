#include "Common/TriangleSoup.h"

#include <algorithm>

namespace shrinkwrap
{

Box TriangleSoup::bounds() const
{
  Box box;
  for (const auto& t : this->triangles)
  {
    for (int v : t)
    {
      box.extend(this->points[v]);
    }
  }
  return box;
}

bool TriangleSoup::allFinite() const
{
  return std::all_of(
    this->points.begin(), this->points.end(), [](const Vec3& p) { return p.allFinite(); });
}

double TriangleSoup::maxTriangleArea() const
{
  double area = 0;
  for (const auto& t : this->triangles)
  {
    const Vec3& a = this->points[t[0]];
    area = std::max(area, 0.5 * (this->points[t[1]] - a).cross(this->points[t[2]] - a).norm());
  }
  return area;
}

double TriangleSoup::area() const
{
  const auto valid = [&](int v) { return v >= 0 && v < static_cast<int>(this->points.size()); };
  double area = 0;
  for (const auto& t : this->triangles)
  {
    if (std::all_of(t.begin(), t.end(), valid))
    {
      const Vec3& a = this->points[t[0]];
      area += 0.5 * (this->points[t[1]] - a).cross(this->points[t[2]] - a).norm();
    }
  }
  return area;
}

} // namespace shrinkwrap
