#include "Distance/WindingNumber.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shrinkwrap
{

WindingNumber::WindingNumber(
  const TriangleSoup& soup, const AABBTree& tree, const WindingNumberSettings& settings)
  : Settings(settings)
{
  const int nt = static_cast<int>(soup.triangles.size());
  this->Corners.reserve(nt);
  for (const auto& tri : soup.triangles)
  {
    this->Corners.push_back({ soup.points[tri[0]], soup.points[tri[1]], soup.points[tri[2]] });
  }
  if (nt == 0)
  {
    return;
  }
  this->Order.resize(nt);
  for (int s = 0; s < nt; ++s)
  {
    this->Order[s] = tree.triangleAt(s);
  }
  this->Nodes.resize(tree.nodes().size());
  this->moments(0, tree.nodes());
}

WindingNumber::WindingNumber(const TriangleSoup& soup, const WindingNumberSettings& settings)
  : WindingNumber(soup, AABBTree(soup), settings)
{
}

// Bottom up: a leaf's moments from its triangles, an inner node's from its children's. The radius
// is the smaller of two bounds: the farthest corner of the node's box, and the children's balls.
void WindingNumber::moments(int index, const HierarchyNodes& tree)
{
  const AABBTree::Node& t = tree[index];
  Node node;
  node.first = t.first;
  node.count = t.count;
  node.dipole = Vec3::Zero();
  node.area = 0;
  Vec3 weighted = Vec3::Zero();
  double childBound = 0;
  if (t.count > 0)
  {
    for (int s = t.first; s < t.first + t.count; ++s)
    {
      const auto& p = this->Corners[this->Order[s]];
      const Vec3 a = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]);
      const double area = a.norm();
      node.dipole += a;
      node.area += area;
      weighted += area * (p[0] + p[1] + p[2]) / 3.0;
    }
    node.center = node.area > 0 ? Vec3(weighted / node.area) : t.box.center();
    childBound = std::numeric_limits<double>::infinity();
  }
  else
  {
    this->moments(t.first, tree);
    this->moments(t.first + 1, tree);
    const Node &l = this->Nodes[t.first], &r = this->Nodes[t.first + 1];
    node.dipole = l.dipole + r.dipole;
    node.area = l.area + r.area;
    node.center =
      node.area > 0 ? Vec3((l.area * l.center + r.area * r.center) / node.area) : t.box.center();
    childBound = std::max(
      (l.center - node.center).norm() + l.radius, (r.center - node.center).norm() + r.radius);
  }
  const Vec3 far =
    (t.box.max - node.center).cwiseAbs().cwiseMax((t.box.min - node.center).cwiseAbs());
  node.radius = std::min(far.norm(), childBound);
  this->Nodes[index] = node;
}

// Van Oosterom & Strackee: tan(Omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| +
// (c.a)|b|), positive where the triangle turns its front (counter-clockwise corners) away from x.
double WindingNumber::solidAngle(int triangle, const Vec3& x) const
{
  const auto& p = this->Corners[triangle];
  const Vec3 a = p[0] - x, b = p[1] - x, c = p[2] - x;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double det = a.dot(b.cross(c));
  const double d = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2 * std::atan2(det, d);
}

double WindingNumber::at(const Vec3& x, int skip, double accuracy) const
{
  if (this->Nodes.empty())
  {
    return 0;
  }
  const double beta = accuracy > 0 ? accuracy : this->Settings.accuracy;
  const double beta2 = beta * beta;
  double sum = 0;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    const Vec3 d = node.center - x;
    const double d2 = d.squaredNorm();
    if (d2 > beta2 * node.radius * node.radius)
    {
      // The dipole's solid angle: area vector . (centre - x) / |centre - x|^3.
      sum += d.dot(node.dipole) / (d2 * std::sqrt(d2));
    }
    else if (node.count > 0)
    {
      for (int s = node.first; s < node.first + node.count; ++s)
      {
        if (this->Order[s] != skip)
        {
          sum += this->solidAngle(this->Order[s], x);
        }
      }
    }
    else if (top + 2 <= 128)
    {
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }
  return sum / (4 * M_PI);
}

double WindingNumber::exactAt(const Vec3& x) const
{
  double sum = 0;
  for (int t = 0; t < static_cast<int>(this->Corners.size()); ++t)
  {
    sum += this->solidAngle(t, x);
  }
  return sum / (4 * M_PI);
}

} // namespace shrinkwrap
