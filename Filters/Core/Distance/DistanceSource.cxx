#include "Distance/DistanceSource.h"
#include "Distance/SoupEdges.h"

#include "Distance/ConfirmedSides.h"
#include "Distance/ConsistentOrientation.h"
#include "Distance/Outline.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

namespace
{
TriangleSoup weldedAndOriented(
  const TriangleSoup& soup, long long& reoriented, std::vector<int>& kept)
{
  TriangleSoup welded = weldDuplicatePoints(soup);
  dropRepeatedTriangles(welded, &kept);
  reoriented = orientConsistently(welded);
  return welded;
}
} // namespace

TriangleSource::TriangleSource(const TriangleSoup& soup)
  : Soup(weldedAndOriented(soup, this->Reoriented, this->Kept))
  , Tree(this->Soup)
  , Normals(this->Soup)
{
}

bool TriangleSource::outline(
  const GridLattice& lattice, const Progress& progress, IndexList& cells) const
{
  return outlineCells(this->Soup, lattice, progress, cells);
}

SourcePoint nearestOf(const ClosestHit& hit)
{
  SourcePoint p;
  if (hit.triangle >= 0)
  {
    p.found = true;
    p.squaredDistance = hit.squaredDistance;
    p.point = hit.point;
    p.element = hit.triangle;
  }
  return p;
}

bool TriangleSource::facesInward(const DistanceGrid& field) const
{
  constexpr int kVotes = 4000;
  const int n = static_cast<int>(this->Soup.triangles.size());
  const int stride = std::max(1, n / kVotes);
  const double h = field.lattice().spacing.maxCoeff();
  long long outward = 0, inward = 0;
  for (int t = 0; t < n; t += stride)
  {
    const Vec3 normal = unitNormal(this->Soup, t);
    if (normal.isZero())
    {
      continue;
    }
    const auto& c = this->Soup.triangles[t];
    const Vec3 centre =
      (this->Soup.points[c[0]] + this->Soup.points[c[1]] + this->Soup.points[c[2]]) / 3;
    const double ahead = field.sample(centre + h * normal).value;
    const double behind = field.sample(centre - h * normal).value;
    outward += ahead > behind;
    inward += ahead < behind;
  }
  return inward > outward;
}

SourcePoint TriangleSource::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  const ClosestHit hit = this->Tree.closestPoint(x, maxSquaredDistance);
  SourcePoint p = nearestOf(hit);
  if (p.found)
  {
    p.normal = this->Normals.at(hit.triangle, hit.feature);
    p.side = (x - hit.point).dot(p.normal);
    p.sure = this->Normals.sure(hit.triangle, hit.feature);
  }
  return p;
}

const WindingNumber& TriangleSource::winding() const
{
  std::call_once(this->WindingBuilt,
    [this] { this->Winding = std::make_unique<WindingNumber>(this->Soup, this->Tree); });
  return *this->Winding;
}

// Where the fast value is within its error of 1/2 (in the plane of a hole, say), again with a far
// field three times farther out, so that the side agrees with the exact sum.
double TriangleSource::windingNumber(const Vec3& x) const
{
  const double w = this->winding().at(x);
  return std::abs(std::abs(w) - 0.5) < 0.05 ? this->winding().at(x, -1, 9.0) : w;
}

const std::vector<char>& TriangleSource::sidesConfirmed() const
{
  std::call_once(
    this->SidesBuilt, [this] { this->Sides = confirmSides(this->Soup, this->winding()); });
  return this->Sides;
}

std::vector<std::array<Vec3, 2>> TriangleSource::rims(double creaseAngle) const
{
  std::vector<std::array<Vec3, 2>> rims;
  const EdgeUses uses = edgeUses(this->Soup);
  const auto& x = this->Soup.points;
  const double cosCrease = std::cos(creaseAngle * M_PI / 180);
  auto crease = [&](const EdgeUse& u, const EdgeUse& v) {
    const Vec3 nu = unitNormal(this->Soup, u.triangle), nv = unitNormal(this->Soup, v.triangle);
    // Two triangles that run along the edge the same way face opposite ways (a Moebius band's
    // seam); a sliver's normal (zero) tells nothing.
    return nu != Vec3::Zero() && nv != Vec3::Zero() &&
      (u.forward != v.forward ? 1 : -1) * nu.dot(nv) < cosCrease;
  };
  forEachEdge(uses, [&](std::size_t first, std::size_t last) {
    const auto& t = this->Soup.triangles[uses[first].triangle];
    const int a = t[uses[first].slot], b = t[(uses[first].slot + 1) % 3];
    const bool rim = last == first + 1;
    if (a != b &&
      (rim || (last == first + 2 && creaseAngle < 180 && crease(uses[first], uses[first + 1]))))
    {
      rims.push_back({ x[a], x[b] });
    }
  });
  return rims;
}

} // namespace shrinkwrap
