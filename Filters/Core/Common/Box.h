// Axis-aligned box in double precision: the bounds of triangles, tree nodes and grids.
#ifndef ShrinkWrap_Box_h
#define ShrinkWrap_Box_h

#include "Common/Vec3.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace shrinkwrap
{

struct Box
{
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return (this->min.array() > this->max.array()).any(); }
  void extend(const Vec3& p)
  {
    this->min = this->min.cwiseMin(p);
    this->max = this->max.cwiseMax(p);
  }
  void extend(const Box& b)
  {
    this->min = this->min.cwiseMin(b.min);
    this->max = this->max.cwiseMax(b.max);
  }
  template <typename Points>
  static Box around(const Points& points) // the bounds of points (empty for none)
  {
    Box box;
    for (const Vec3& p : points)
    {
      box.extend(p);
    }
    return box;
  }
  template <typename Ids>
  static Box around(
    const std::vector<Vec3>& points, const Ids& ids) // the bounds of points[ids] (a triangle's)
  {
    Box box;
    for (const auto id : ids)
    {
      box.extend(points[id]);
    }
    return box;
  }
  Vec3 size() const { return this->empty() ? Vec3::Zero() : Vec3(this->max - this->min); }
  Vec3 center() const { return 0.5 * (this->min + this->max); }
  double diagonal() const { return this->size().norm(); }
  // Half the surface area: the surface-area heuristic only compares ratios.
  double halfArea() const
  {
    const Vec3 s = this->size();
    return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
  }
  Box widened(double margin) const // by margin on every side
  {
    return { this->min - Vec3::Constant(margin), this->max + Vec3::Constant(margin) };
  }
  bool overlaps(const Box& b) const
  {
    return (this->min.array() <= b.max.array()).all() && (b.min.array() <= this->max.array()).all();
  }
  // Squared distance from p to the box (0 inside).
  double squaredDistance(const Vec3& p) const
  {
    const Vec3 d = (this->min - p).cwiseMax(p - this->max).cwiseMax(0.0);
    return d.squaredNorm();
  }
};

} // namespace shrinkwrap

#endif
