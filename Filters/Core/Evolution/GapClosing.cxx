#include "Evolution/GapClosing.h"

#include "Common/Parallel.h"
#include "Distance/ClosestPointSweep.h"
#include "Distance/DistanceSource.h"
#include "Distance/GridRegions.h"

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

namespace
{
std::array<int, 6> wholeGrid(const GridLattice& lattice)
{
  return { 0, lattice.dims[0] - 1, 0, lattice.dims[1] - 1, 0, lattice.dims[2] - 1 };
}

// The nodes of D, and with `fillCavities` those of the complement that the grid's border does not
// reach through it.
NodeFlags dilationNodes(const DistanceGrid& field, double radius, bool fillCavities)
{
  const FieldValues& d = field.values();
  NodeFlags inside(d.size());
  parallelFor(0, static_cast<Index>(d.size()), kCheapGrain, [&](Index b, Index e) {
    for (Index n = b; n < e; ++n)
    {
      inside[n] = d[n] < radius;
    }
  });
  if (!fillCavities)
  {
    return inside;
  }
  const NodeFlags reached = reachedFromBorder(field.lattice(), inside);
  parallelFor(0, static_cast<Index>(d.size()), kCheapGrain, [&](Index b, Index e) {
    for (Index n = b; n < e; ++n)
    {
      inside[n] = !reached[n];
    }
  });
  return inside;
}

// The nodes within a cell of D's boundary by their distance to the target (every node with a
// neighbour across it), but for those of filled cavities; ascending. Found in fixed ranges on all
// cores, joined in order.
IndexList nodesNearBoundary(const DistanceGrid& field, double r, const NodeFlags& inside)
{
  const double width = field.lattice().spacing.maxCoeff();
  const FieldValues& d = field.values();
  constexpr Index kRanges = 64;
  const auto total = static_cast<Index>(d.size());
  std::vector<IndexList> found(kRanges);
  parallelFor(0, kRanges, 1, [&](Index b, Index e) {
    for (Index range = b; range < e; ++range)
    {
      for (Index n = total * range / kRanges; n < total * (range + 1) / kRanges; ++n)
      {
        if (std::abs(d[n] - r) < width && (d[n] < r || !inside[n]))
        {
          found[range].push_back(static_cast<std::int64_t>(n));
        }
      }
    }
  });
  IndexList nodes;
  for (const IndexList& part : found)
  {
    nodes.insert(nodes.end(), part.begin(), part.end());
  }
  return nodes;
}

// A point of D's boundary, with D's outward normal there.
struct Front
{
  Vec3 point, normal;
};

// From node n, r beyond the target's closest point p on the line from p through the node (on the
// node's side of the target); without the target, down the grid's gradient.
bool projectOnFront(
  const DistanceGrid& field, const DistanceSource* target, double r, std::int64_t n, Front& front)
{
  const GridLattice& lattice = field.lattice();
  const std::array<int, 3> c = lattice.coordinates(n);
  const Vec3 x = lattice.position(c);
  const double d = field.values()[n];
  if (target)
  {
    const double reach = std::abs(d) + 2 * lattice.spacing.maxCoeff();
    const SourcePoint p = target->closestPoint(x, reach * reach);
    const double distance = std::sqrt(p.squaredDistance);
    if (!p.found || !(distance > 0))
    {
      return false;
    }
    front.normal = (d < 0 ? -1.0 : 1.0) / distance * (x - p.point);
    front.point = p.point + r * front.normal;
    return true;
  }
  Vec3 gradient;
  for (int a = 0; a < 3; ++a)
  {
    std::array<int, 3> lo = c, hi = c;
    lo[a] = std::max(0, c[a] - 1);
    hi[a] = std::min(lattice.dims[a] - 1, c[a] + 1);
    gradient[a] = (field.values()[lattice.index(hi[0], hi[1], hi[2])] -
                    field.values()[lattice.index(lo[0], lo[1], lo[2])]) /
      ((hi[a] - lo[a]) * lattice.spacing[a]);
  }
  const double norm = gradient.norm();
  front.normal = gradient / norm;
  front.point = x - (d - r) * front.normal;
  return norm > 0;
}

// Whether the front point is on D's boundary: no other part of the target within r of it. Where
// one is, the point lies inside D, past a crease where two fronts meet; projected in turn onto
// each front (r from the nearest target point) it moves onto the crease. Without the target, the
// grid's value there.
bool onBoundary(const DistanceGrid& field, const DistanceSource* target, double r, Front& front)
{
  const double cell = field.lattice().spacing.maxCoeff();
  if (!target)
  {
    return field.sample(front.point).value > r - 0.05 * cell;
  }
  for (int turn = 0; turn < 8; ++turn)
  {
    const SourcePoint nearer = target->closestPoint(front.point, r * r);
    const double distance = std::sqrt(nearer.squaredDistance);
    if (!nearer.found || distance > r - 1e-6 * cell)
    {
      return true;
    }
    if (!(distance > 0) || field.sample(front.point).value < 0)
    {
      return false; // inside the target (its grid's sign survives a dirty target)
    }
    front.normal = (front.point - nearer.point) / distance;
    front.point = nearer.point + r * front.normal;
  }
  return false;
}

// Whether the front faces a filled cavity: the first node off D out along its normal, within two
// cells, is in one (or there is none).
bool facesCavity(const DistanceGrid& field, double r, const NodeFlags& inside, const Front& front)
{
  const GridLattice& lattice = field.lattice();
  const double cell = lattice.spacing.maxCoeff();
  for (int k = 1; k <= 4; ++k)
  {
    const Vec3 z = front.point + 0.5 * k * cell * front.normal;
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a)
    {
      c[a] = static_cast<int>(std::clamp(
        std::round((z[a] - lattice.origin[a]) / lattice.spacing[a]), 0.0, lattice.dims[a] - 1.0));
    }
    const std::int64_t n = lattice.index(c[0], c[1], c[2]);
    if (field.values()[n] >= r)
    {
      return inside[n];
    }
  }
  return true;
}

// A point of D's boundary near node n, if there is one. From a node outside D it is the node's
// nearest boundary point (every point of the target is at least d - (d - r) from it); from a node
// inside, where no other part of the target comes nearer, its nearest too (e = r - d: the closing's
// distance is d); else on a crease.
bool boundaryPoint(const DistanceGrid& field, const DistanceSource* target, double r,
  const NodeFlags& inside, bool fillCavities, std::int64_t n, Vec3& site)
{
  const double d = field.values()[n];
  const bool outside = d >= r;
  Front front;
  if ((outside && inside[n]) ||
    !projectOnFront(field, target, r, n, front)) // a filled cavity's node
  {
    return false;
  }
  site = front.point;
  if (outside)
  {
    return true;
  }
  const bool found =
    onBoundary(field, target, r, front) && !(fillCavities && facesCavity(field, r, inside, front));
  site = front.point;
  return found;
}
} // namespace

namespace
{
// The closing's sites: a boundary point of D for each node near its boundary (found: it has one).
struct ClosingSites
{
  IndexList near;
  SiteList sites;
  std::vector<char> found;
};

// False when `progress` asked to stop (reported over batches of nodes).
bool closingSites(const DistanceGrid& field, const DistanceSource* target, double radius,
  const NodeFlags& inside, bool fillCavities, const Progress& progress, ClosingSites& c)
{
  c.near = nodesNearBoundary(field, radius, inside);
  c.sites.resize(c.near.size());
  c.found.resize(c.near.size());
  return forChunks(
    static_cast<long long>(c.near.size()), 16, progress, [&](long long b, long long e) {
      for (long long s = b; s < e; ++s)
      {
        c.found[s] =
          boundaryPoint(field, target, radius, inside, fillCavities, c.near[s], c.sites[s]);
      }
    });
}

// The closed field's values from the distances e to the nearest site, written over e (each node
// reads its own e first: a fine field's closing holds no array of its own for them). Inside D, e >=
// r - d (the ball of radius r - d about a node lies in D), with equality where no other part of the
// target is nearer than r to the node's own front point. The passes find a site near the nearest
// boundary point, not always on it: where they leave e above r - d outside the target, the node's
// own boundary point decides (its distance bounds e from above, and equals r - d where it is
// clear). Inside the target, where the wrap never goes, r - e only bounds d. False when `progress`
// asked to stop (reported over batches of nodes). `nearSlot`: a node-sized scratch (the passes'
// sites, no longer needed) for the slot of each near node in `c`.
bool closedValues(const DistanceGrid& field, const DistanceSource* target, double radius,
  const NodeFlags& inside, bool fillCavities, const ClosingSites& c,
  LargeVector<std::int32_t>& nearSlot, const Progress& progress, FieldValues& e)
{
  const GridLattice& lattice = field.lattice();
  std::fill(nearSlot.begin(), nearSlot.end(), -1);
  for (std::size_t s = 0; s < c.near.size(); ++s)
  {
    nearSlot[c.near[s]] = static_cast<std::int32_t>(s);
  }
  const FieldValues& d = field.values();
  const float r = static_cast<float>(radius);
  const float hair = static_cast<float>(1e-3 * lattice.spacing.maxCoeff());
  return forChunks(lattice.nodeCount(), 8, progress, [&](long long b, long long end) {
    for (long long n = b; n < end; ++n)
    {
      if (!inside[n])
      {
        e[n] = d[n];
        continue;
      }
      double nearest = e[n];
      if (d[n] >= 0 && r - e[n] < d[n] - hair)
      {
        // A node near the boundary has its boundary point from above.
        const std::int32_t s = nearSlot[n];
        Vec3 site;
        const bool has = s >= 0
          ? (site = c.sites[s], c.found[s] != 0)
          : boundaryPoint(field, target, radius, inside, fillCavities, n, site);
        if (has)
        {
          nearest = std::min(nearest, (site - lattice.position(lattice.coordinates(n))).norm());
        }
      }
      e[n] = std::min(d[n], static_cast<float>(radius - nearest));
    }
  });
}
} // namespace

Status closingField(const DistanceGrid& field, double radius, const DistanceSource* target,
  bool fillCavities, DistanceGrid& closed, const Progress& progress)
{
  const GridLattice& lattice = field.lattice();
  if (!(radius >= 0.25 * lattice.spacing.minCoeff()))
  {
    closed = field;
    return {};
  }
  const NodeFlags inside = dilationNodes(field, radius, fillCavities);
  bool border = false;
  forEachFaceNode(
    lattice, wholeGrid(lattice), [&](std::int64_t n) { border = border || inside[n]; });
  if (border || std::find(inside.begin(), inside.end(), 1) == inside.end())
  {
    return Status::failure(
      "the target dilated by half the Gap Size is empty or reaches the border of the "
      "distance field; lower the Gap Size, or give a Distance Field with more room around the "
      "target (Offset Factor of Mesh Signed Distance)");
  }
  const Status aborted = Status::failure("aborted");
  if (!progress.report(0.2))
  {
    return aborted;
  }
  // The sites: boundary points from the nodes near it, one each; the closest-point passes spread
  // them (they overwrite siteOfNode).
  ClosingSites c;
  if (!closingSites(field, target, radius, inside, fillCavities, progress.stage(0.2, 0.4), c))
  {
    return aborted;
  }
  LargeVector<std::int32_t> siteOfNode(lattice.nodeCount(), -1);
  for (std::size_t s = 0; s < c.near.size(); ++s)
  {
    siteOfNode[c.near[s]] = c.found[s] ? static_cast<std::int32_t>(s) : -1;
  }
  FieldValues e(lattice.nodeCount());
  if (!progress.report(0.4) ||
    !sweepClosestPoints(lattice, c.sites, siteOfNode.data(), e.data(), progress.stage(0.4, 0.9)))
  {
    return aborted;
  }
  if (!closedValues(
        field, target, radius, inside, fillCavities, c, siteOfNode, progress.stage(0.9, 1), e))
  {
    return aborted;
  }
  closed = DistanceGrid(lattice, std::move(e));
  return progress.report(1) ? Status() : aborted;
}

} // namespace shrinkwrap
