#include "Surface/SelfIntersections.h"

#include "Common/Box.h"
#include "Common/Parallel.h"
#include "Surface/TriangleGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>

namespace shrinkwrap
{

namespace
{
int sign(double v)
{
  return (v > 0) - (v < 0);
}

// The sign of the volume of the tetrahedron (a, b, c, d).
int orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return sign(tripleProduct(b - a, c - a, d - a));
}

// Whether the open segment pq passes through the triangle abc (strictly on both sides of its
// plane).
bool segmentCrosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const int sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq)
  {
    return false;
  }
  const int s1 = orientation(p, q, a, b), s2 = orientation(p, q, b, c),
            s3 = orientation(p, q, c, a);
  return (s1 >= 0 && s2 >= 0 && s3 >= 0 && (s1 | s2 | s3)) ||
    (s1 <= 0 && s2 <= 0 && s3 <= 0 && (s1 | s2 | s3));
}

// A triangle by its corners and their vertex ids (-1: a new point, shared with nothing), with its
// plane n . y = offset (|n| = 1) for the cheap first test of a pair.
struct Facet
{
  std::array<Vec3, 3> p;
  std::array<int, 3> id;
  Vec3 n;
  double offset;
};

Facet facetAt(const std::array<Vec3, 3>& p, const std::array<int, 3>& id)
{
  Facet f{ p, id, (p[1] - p[0]).cross(p[2] - p[0]), 0 };
  const double length = f.n.norm();
  f.n = length > 0 ? Vec3(f.n / length) : Vec3::Zero();
  f.offset = f.n.dot(p[0]);
  return f;
}

Facet facetOf(const std::vector<Vec3>& x, const std::array<int, 3>& t)
{
  return facetAt({ x[t[0]], x[t[1]], x[t[2]] }, t);
}

bool has(const std::array<int, 3>& ids, int v)
{
  return v >= 0 && (v == ids[0] || v == ids[1] || v == ids[2]);
}

// Whether the corners of f that e does not share lie clearly (beyond `margin`) on one side of the
// plane of e: then f meets that plane at most in the shared corner, so the two cannot cross.
bool oneSide(const Facet& e, const Facet& f, double margin)
{
  int above = 0, below = 0, own = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (!has(e.id, f.id[k]))
    {
      const double h = e.n.dot(f.p[k]) - e.offset;
      above += h > margin;
      below += h < -margin;
      ++own;
    }
  }
  return above == own || below == own;
}

// Whether triangles s and t cross, ignoring what they share: with one shared vertex only the edges
// opposite it can cross the other triangle; with two (a shared edge) they are neighbours.
bool crosses(const Facet& s, const Facet& t, double margin)
{
  const int shared = has(t.id, s.id[0]) + has(t.id, s.id[1]) + has(t.id, s.id[2]);
  if (shared >= 2 || oneSide(s, t, margin) || oneSide(t, s, margin))
  {
    return false;
  }
  auto edgesThrough = [&](const Facet& e, const Facet& f) {
    for (int k = 0; k < 3; ++k)
    {
      const int q = (k + 1) % 3;
      if (!has(f.id, e.id[k]) && !has(f.id, e.id[q]) &&
        segmentCrosses(e.p[k], e.p[q], f.p[0], f.p[1], f.p[2]))
      {
        return true;
      }
    }
    return false;
  };
  return edgesThrough(s, t) || edgesThrough(t, s);
}

// A guarded question's box (an edit's new triangles) is at most this many grid cells wide, but for
// rare wide fans: where a guard holds a few boxes, the triangles and the edits of a pass are binned
// only within that reach of them. Many boxes (thousands where the hold-back kept two parts apart)
// lie all over the surface, and picking the triangles near them costs more than it saves.
constexpr double kQuestionCells = 4;
constexpr std::size_t kFewBoxes = 32;

// Closer to a plane than this goes the exact way (orientations) rather than the plane test.
double roundingMargin(const TriangleGrid& grid)
{
  return 1e-7 * grid.cell();
}

// The pairs each(b, e, out) finds over chunks [b, e) of [0, n), from all threads, in one order
// whatever the threads did. `stop` (empty: never) is asked between up to kStopBatches batches of at
// least kCheapGrain items (a small search runs as one loop: each batch starts the threads anew), on
// the calling thread; a stopped search returns the pairs found so far.
constexpr Index kStopBatches = 8;
template <typename Each>
std::vector<std::pair<int, int>> pairsInParallel(
  Index n, Index grain, Each&& each, const std::function<bool()>& stop)
{
  std::vector<std::pair<int, int>> pairs;
  std::mutex lock;
  const Index batches = stop ? std::clamp<Index>(n / kCheapGrain, 1, kStopBatches) : 1;
  for (Index k = 0; k < batches && !(k > 0 && stop()); ++k)
  {
    parallelFor(n * k / batches, n * (k + 1) / batches, grain, [&](Index b, Index e) {
      std::vector<std::pair<int, int>> found;
      each(b, e, found);
      const std::lock_guard<std::mutex> guard(lock);
      pairs.insert(pairs.end(), found.begin(), found.end());
    });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// The pairs of triangles that cross at x, found through the grid (boxes at x or containing them).
std::vector<std::pair<int, int>> crossingPairs(const TriangleGrid& grid, const std::vector<Vec3>& x,
  const std::vector<std::array<int, 3>>& triangles, const std::function<bool()>& stop)
{
  const double margin = roundingMargin(grid);
  std::vector<Facet> facets(triangles.size());
  // Two triangles cross only where both boxes hold the crossing point: boxes at x (the grid's may
  // be wider, swept over a step), widened by the margin against rounding, rule a pair out before
  // its planes are asked.
  std::vector<Box> boxes(triangles.size());
  parallelFor(0, static_cast<Index>(triangles.size()), kCheapGrain, [&](Index b, Index e) {
    for (Index t = b; t < e; ++t)
    {
      facets[t] = facetOf(x, triangles[t]);
      boxes[t] = Box::around(facets[t].p).widened(margin);
    }
  });
  return pairsInParallel(
    grid.bucketCount(), 0,
    [&](Index b, Index e, std::vector<std::pair<int, int>>& found) {
      grid.forEachOverlappingPair(static_cast<int>(b), static_cast<int>(e), [&](int s, int t) {
        if (boxes[s].overlaps(boxes[t]) && crosses(facets[s], facets[t], margin))
        {
          found.emplace_back(s, t);
        }
      });
    },
    stop);
}

// The pairs that cross at x with a triangle in `changed` (sorted), each once.
std::vector<std::pair<int, int>> crossingsAmong(const TriangleGrid& grid,
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles,
  const std::vector<int>& changed, const std::function<bool()>& stop)
{
  const double margin = roundingMargin(grid);
  const auto n = static_cast<Index>(changed.size());
  return pairsInParallel(
    n, kQueryGrain,
    [&](Index b, Index e, std::vector<std::pair<int, int>>& found) {
      for (Index k = b; k < e; ++k)
      {
        const int s = changed[k];
        const Facet fs = facetOf(x, triangles[s]);
        const Box near = Box::around(fs.p).widened(margin);
        grid.forEachNear(near, [&](int t) {
          // A pair of two changed triangles is met twice; it is kept once.
          const bool counted = t < s && std::binary_search(changed.begin(), changed.end(), t);
          if (t != s && !counted && near.overlaps(Box::around(x, triangles[t]).widened(margin)) &&
            crosses(fs, facetOf(x, triangles[t]), margin))
          {
            found.emplace_back(s, t);
          }
        });
      }
    },
    stop);
}

// Few changed triangles (a step's touch-ups, a round of edits) are tested alone; many, all pairs in
// parallel.
std::vector<std::pair<int, int>> crossingsOf(const TriangleGrid& grid, const std::vector<Vec3>& x,
  const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& changed,
  const std::function<bool()>& stop)
{
  return 8 * changed.size() < triangles.size() ? crossingsAmong(grid, x, triangles, changed, stop)
                                               : crossingPairs(grid, x, triangles, stop);
}

// For each of `points`, the vertex of `mesh` at exactly the same position (-1: none), through a
// sorted table of the positions' bits.
std::vector<int> samePositions(const SurfaceMesh& mesh, const std::vector<Vec3>& points)
{
  auto hash = [](const Vec3& p) {
    std::uint64_t h = 0;
    for (int k = 0; k < 3; ++k)
    {
      std::uint64_t bits;
      std::memcpy(&bits, p.data() + k, sizeof bits);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
      h ^= h >> 29;
    }
    return h;
  };
  std::vector<std::pair<std::uint64_t, int>> table(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    table[v] = { hash(mesh.points()[v]), v };
  }
  std::sort(table.begin(), table.end());
  std::vector<int> same(points.size(), -1);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const std::uint64_t h = hash(points[i]);
    for (auto it = std::lower_bound(table.begin(), table.end(), std::make_pair(h, -1));
         it != table.end() && it->first == h; ++it)
    {
      if (mesh.points()[it->second] == points[i])
      {
        same[i] = it->second;
        break;
      }
    }
  }
  return same;
}

// Whether `mesh` has the triangle (a, b, c), in that orientation.
bool hasTriangle(const SurfaceMesh& mesh, int a, int b, int c)
{
  const int p = a < 0 || b < 0 || c < 0 ? -1 : mesh.ringEntry(a, b);
  return p >= 0 && mesh.ring(mesh.next(a, p)) == c;
}

SelfIntersections fromPairs(
  std::size_t triangleCount, const std::vector<std::pair<int, int>>& pairs)
{
  SelfIntersections found;
  found.intersecting.assign(triangleCount, 0);
  for (const auto& st : pairs)
  {
    ++found.pairs;
    found.intersecting[st.first] = found.intersecting[st.second] = 1;
  }
  return found;
}
} // namespace

SelfIntersections findSelfIntersections(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  const TriangleGrid grid(x, triangles);
  if (triangles.size() < 2 || grid.empty())
  {
    return fromPairs(triangles.size(), {});
  }
  return fromPairs(triangles.size(), crossingPairs(grid, x, triangles, {}));
}

SelfIntersections findNewSelfIntersections(const SurfaceMesh& before, const std::vector<Vec3>& x,
  const std::vector<std::array<int, 3>>& triangles, const std::function<bool()>& stop)
{
  const auto stopped = [&] { return stop && stop(); };
  if (stopped())
  {
    return fromPairs(triangles.size(), {});
  }
  const std::vector<int> same = samePositions(before, x);
  std::vector<int> made;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    const auto& v = triangles[t];
    if (!hasTriangle(before, same[v[0]], same[v[1]], same[v[2]]))
    {
      made.push_back(t);
    }
  }
  if (stopped())
  {
    return fromPairs(triangles.size(), {});
  }
  if (made.empty() || triangles.size() < 2)
  {
    return fromPairs(triangles.size(), {});
  }
  const TriangleGrid grid(x, triangles);
  if (grid.empty() || stopped())
  {
    return fromPairs(triangles.size(), {});
  }
  return fromPairs(triangles.size(), crossingsOf(grid, x, triangles, made, stop));
}

std::vector<Box> boxesAround(const std::vector<Vec3>& points,
  const std::vector<std::array<int, 3>>& triangles, const SelfIntersections& found, double reach)
{
  std::vector<Box> boxes;
  for (std::size_t t = 0; t < found.intersecting.size(); ++t)
  {
    if (found.intersecting[t])
    {
      boxes.push_back(Box::around(points, triangles[t]).widened(reach));
    }
  }
  return boxes;
}

std::vector<Box> cellsCovering(const std::vector<Box>& boxes, double cell)
{
  if (!(cell > 0) || !std::isfinite(cell))
  {
    return boxes;
  }
  std::vector<std::array<std::int64_t, 3>> cells;
  for (const Box& box : boxes)
  {
    if (box.empty() || !box.min.allFinite() || !box.max.allFinite())
    {
      continue;
    }
    const Eigen::Array3d lo = (box.min / cell).array().floor(),
                         hi = (box.max / cell).array().floor();
    // Cells far smaller than the boxes (the boxes themselves are the fewer), or beyond integers.
    if (((hi - lo) > 64).any() || (lo.abs() > 1e15).any() || (hi.abs() > 1e15).any())
    {
      return boxes;
    }
    for (double k = lo[2]; k <= hi[2]; ++k)
      for (double j = lo[1]; j <= hi[1]; ++j)
        for (double i = lo[0]; i <= hi[0]; ++i)
        {
          cells.push_back({ static_cast<std::int64_t>(i), static_cast<std::int64_t>(j),
            static_cast<std::int64_t>(k) });
        }
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<Box> covering;
  for (const auto& c : cells)
  {
    const Vec3 corner =
      cell * Vec3(static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2]));
    covering.push_back({ corner, corner + Vec3::Constant(cell) });
  }
  return covering;
}

CrossingGuard::CrossingGuard(const std::vector<Vec3>& points,
  const std::vector<std::array<int, 3>>& triangles, std::vector<Box> only)
  : Points(points)
  , Triangles(triangles)
  , Only(std::move(only))
  , IndexAll(this->Only.empty() || this->Only.size() > kFewBoxes)
{
  const bool binnable = std::all_of(this->Only.begin(), this->Only.end(),
    [](const Box& box) { return !box.empty() && box.min.allFinite() && box.max.allFinite(); });
  if (!this->Only.empty() && binnable)
  {
    double size = 0;
    for (const Box& box : this->Only)
    {
      size += box.size().maxCoeff() / static_cast<double>(this->Only.size());
      this->OnlyAround.extend(box);
    }
    this->OnlyBinned = std::make_unique<TriangleGrid>(this->Only, size);
  }
}

// Built at the first question; rebuilt with every triangle once a question is wider than the reach.
const TriangleGrid& CrossingGuard::grid()
{
  if (!this->Grid)
  {
    if (!(this->Cell > 0))
    {
      this->Cell = TriangleGrid::cellSizeFor(this->Points, this->Triangles);
      this->Reach = kQuestionCells * this->Cell;
    }
    std::vector<Box> boxes;
    this->Ids.clear();
    if (this->IndexAll)
    {
      boxes.reserve(this->Triangles.size());
      this->Ids.reserve(this->Triangles.size());
    }
    for (int t = 0; t < static_cast<int>(this->Triangles.size()); ++t)
    {
      const Box box = Box::around(this->Points, this->Triangles[t]);
      if (this->IndexAll || this->guards(box.widened(this->Reach)))
      {
        boxes.push_back(box);
        this->Ids.push_back(t);
      }
    }
    this->Grid = std::make_unique<TriangleGrid>(std::move(boxes), this->Cell, this->Stop);
    this->EditCells.clear();
    if (this->Grid->stopped())
    {
      return *this->Grid; // no edit is made from here
    }
    for (std::size_t e = 0; e < this->Edits.size(); ++e)
    {
      this->index(static_cast<int>(e));
    }
  }
  return *this->Grid;
}

void CrossingGuard::index(int e)
{
  if (!this->IndexAll && !this->guards(this->Edits[e].box.widened(this->Reach)))
  {
    return; // no question within the reach can meet it
  }
  const TriangleGrid::Range r = this->Grid->rangeOf(this->Edits[e].box);
  for (std::uint32_t k = r[2]; k <= r[5]; ++k)
    for (std::uint32_t j = r[1]; j <= r[4]; ++j)
      for (std::uint32_t i = r[0]; i <= r[3]; ++i)
      {
        this->EditCells[TriangleGrid::key(i, j, k)].push_back(e);
      }
}

const Vec3& CrossingGuard::position(int v) const
{
  return !this->Merged.empty() && this->Merged[v] == kKept ? this->MovedTo[v] : this->Points[v];
}

// The merged vertex keeps keep's id: no triangle of the surface asked about holds it (they are
// skipped as replaced), nor does an earlier edit (keep was untouched by the pass).
std::vector<CrossingGuard::Made> CrossingGuard::fan(
  int keep, const Vec3& m, const std::vector<std::array<int, 2>>& rim) const
{
  std::vector<Made> made;
  made.reserve(rim.size());
  for (const auto& uw : rim)
  {
    const std::array<Vec3, 3> p{ m, this->position(uw[0]), this->position(uw[1]) };
    made.push_back({ p, { keep, uw[0], uw[1] }, Box::around(p) });
  }
  return made;
}

// The new triangles share two vertices with each old one, so `crosses` passes over those.
std::vector<CrossingGuard::Made> CrossingGuard::flipped(int i, int j, int c, int d) const
{
  const std::vector<Vec3>& x = this->Points;
  const std::array<Vec3, 3> p{ x[i], x[c], x[d] }, q{ x[j], x[d], x[c] };
  return { { p, { i, c, d }, Box::around(p) }, { q, { j, d, c }, Box::around(q) } };
}

bool CrossingGuard::collapseCrosses(
  int keep, int gone, const Vec3& m, const std::vector<std::array<int, 2>>& rim)
{
  return this->anyCrosses(this->fan(keep, m, rim), keep, gone);
}

void CrossingGuard::addCollapse(
  int keep, int gone, const Vec3& m, const std::vector<std::array<int, 2>>& rim)
{
  this->add(this->fan(keep, m, rim));
  if (this->Merged.empty())
  {
    this->Merged.assign(this->Points.size(), 0);
    this->MovedTo.resize(this->Points.size());
  }
  this->Merged[keep] = kKept;
  this->Merged[gone] = kGone;
  this->MovedTo[keep] = m;
}

bool CrossingGuard::flipCrosses(int i, int j, int c, int d)
{
  return this->anyCrosses(this->flipped(i, j, c, d), -1, -1);
}

void CrossingGuard::addFlip(int i, int j, int c, int d)
{
  this->add(this->flipped(i, j, c, d));
}

bool CrossingGuard::guards(const Box& box) const
{
  if (this->Only.empty())
  {
    return true;
  }
  bool guarded = false;
  if (this->OnlyBinned && !this->OnlyBinned->empty())
  {
    if (!this->OnlyAround.overlaps(box))
    {
      return false; // most edits lie far from every guarded box
    }
    this->OnlyBinned->forEachNear(box, [&guarded](int) { guarded = true; });
    return guarded;
  }
  // Boxes the grid cannot bin (empty, degenerate, not finite).
  return std::any_of(
    this->Only.begin(), this->Only.end(), [&box](const Box& only) { return only.overlaps(box); });
}

// One grid query for all the new triangles; each is then tested against the candidates its own box
// overlaps.
bool CrossingGuard::anyCrosses(const std::vector<Made>& made, int a, int b)
{
  Box all;
  for (const Made& m : made)
  {
    all.extend(m.box);
  }
  if (!this->guards(all))
  {
    return false;
  }
  if (this->grid().stopped()) // the reach is known from here
  {
    return true;
  }
  if (!this->IndexAll && !(all.size().maxCoeff() <= this->Reach))
  {
    // A question wider than the reach may meet triangles and edits left out: from now on, none is.
    this->IndexAll = true;
    this->Grid.reset();
  }
  const TriangleGrid& grid = this->grid();
  if (grid.stopped())
  {
    return true;
  }
  std::vector<Facet> facets;
  for (const Made& m : made)
  {
    facets.push_back(facetAt(m.p, m.id));
  }
  const double margin = roundingMargin(grid);
  bool crossing = false;
  auto test = [&](const Box& box, const auto& facetOfOther) {
    std::optional<Facet> other; // made for the first new triangle whose box it overlaps
    for (std::size_t f = 0; f < made.size() && !crossing; ++f)
    {
      if (made[f].box.overlaps(box))
      {
        if (!other)
        {
          other = facetOfOther();
        }
        crossing = crosses(facets[f], *other, margin);
      }
    }
  };
  grid.forEachNear(all, [&](int binned) {
    const int t = this->Ids[binned];
    const auto& tri = this->Triangles[t];
    const bool replaced = !this->Merged.empty() &&
      (this->Merged[tri[0]] || this->Merged[tri[1]] || this->Merged[tri[2]]);
    if (!crossing && !replaced && !has(tri, a) && !has(tri, b))
    {
      test(grid.box(binned), [&] { return facetOf(this->Points, tri); });
    }
  });
  // The pass's own edits, binned in the same cells.
  std::vector<int> earlier;
  const TriangleGrid::Range r = grid.rangeOf(all);
  for (std::uint32_t k = r[2]; k <= r[5] && !crossing && !this->EditCells.empty(); ++k)
    for (std::uint32_t j = r[1]; j <= r[4]; ++j)
      for (std::uint32_t i = r[0]; i <= r[3]; ++i)
      {
        const auto cell = this->EditCells.find(TriangleGrid::key(i, j, k));
        if (cell != this->EditCells.end())
        {
          earlier.insert(earlier.end(), cell->second.begin(), cell->second.end());
        }
      }
  std::sort(earlier.begin(), earlier.end());
  earlier.erase(std::unique(earlier.begin(), earlier.end()), earlier.end());
  for (std::size_t n = 0; n < earlier.size() && !crossing; ++n)
  {
    const Made& e = this->Edits[earlier[n]];
    test(e.box, [&] { return facetAt(e.p, e.id); });
  }
  return crossing;
}

// Recorded everywhere (a wider question may yet ask for all), but indexed in the grid's cells only
// once a question needs the grid (where the guard covers a few boxes, most passes ask none).
void CrossingGuard::add(const std::vector<Made>& made)
{
  for (const Made& m : made)
  {
    this->Edits.push_back(m);
    if (this->Grid && !this->Grid->stopped())
    {
      this->index(static_cast<int>(this->Edits.size()) - 1);
    }
  }
}

namespace
{
// Each triangle's box swept from `previous` to `next`, and the triangles that move (two that stay
// cannot begin to cross).
std::vector<Box> sweptBoxes(const std::vector<Vec3>& previous, const std::vector<Vec3>& next,
  const std::vector<std::array<int, 3>>& triangles, std::vector<int>& moving)
{
  std::vector<Box> swept(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    bool moves = false;
    for (int v : triangles[t])
    {
      swept[t].extend(previous[v]);
      swept[t].extend(next[v]);
      moves = moves || next[v] != previous[v];
    }
    if (moves)
    {
      moving.push_back(static_cast<int>(t));
    }
  }
  return swept;
}

// Per vertex v of `vertices` its triangles: triangles[at[v] .. at[v + 1]).
struct VertexTriangles
{
  std::vector<int> at, triangles;
  VertexTriangles(const std::vector<std::array<int, 3>>& all, std::size_t vertices)
    : at(vertices + 1, 0)
  {
    for (const auto& tri : all)
    {
      for (int v : tri)
      {
        ++this->at[v + 1];
      }
    }
    for (std::size_t v = 0; v < vertices; ++v)
    {
      this->at[v + 1] += this->at[v];
    }
    this->triangles.resize(this->at.back());
    std::vector<int> fill(this->at.begin(), this->at.end() - 1);
    for (std::size_t t = 0; t < all.size(); ++t)
    {
      for (int v : all[t])
      {
        this->triangles[fill[v]++] = static_cast<int>(t);
      }
    }
  }
  // The triangles around `vertices`, each once, in order.
  std::vector<int> around(const std::vector<int>& vertices) const
  {
    std::vector<int> found;
    for (int v : vertices)
    {
      found.insert(found.end(), this->triangles.begin() + this->at[v],
        this->triangles.begin() + this->at[v + 1]);
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }
};
} // namespace

int holdNewCrossings(const std::vector<Vec3>& previous, std::vector<Vec3>& next,
  const std::vector<std::array<int, 3>>& triangles, std::vector<int>* crossing,
  const std::function<bool()>& stop)
{
  const auto stopped = [&] { return stop && stop(); };
  std::vector<int> moving;
  std::vector<Box> swept = sweptBoxes(previous, next, triangles, moving);
  if (moving.empty() || stopped())
  {
    return 0;
  }
  const TriangleGrid grid(std::move(swept), TriangleGrid::cellSizeFor(next, triangles));
  if (triangles.size() < 2 || grid.empty() || stopped())
  {
    return 0;
  }
  const double margin = roundingMargin(grid);
  auto isNew = [&](int s, int t) {
    return !crosses(facetOf(previous, triangles[s]), facetOf(previous, triangles[t]), margin);
  };
  std::vector<std::pair<int, int>> found = crossingsOf(grid, next, triangles, moving, stop);
  std::unique_ptr<VertexTriangles> around; // built when a first vertex is held
  int held = 0;
  while (!found.empty() && !stopped())
  {
    std::vector<int> moved; // the vertices this round holds
    for (const auto& st : found)
    {
      if (!isNew(st.first, st.second))
      {
        continue;
      }
      if (crossing)
      {
        crossing->insert(crossing->end(), { st.first, st.second });
      }
      for (int t : { st.first, st.second })
      {
        for (int v : triangles[t])
        {
          if (next[v] != previous[v])
          {
            next[v] = previous[v];
            moved.push_back(v);
          }
        }
      }
    }
    if (moved.empty())
    {
      break;
    }
    held += static_cast<int>(moved.size());
    if (!around)
    {
      around = std::make_unique<VertexTriangles>(triangles, next.size());
    }
    // Only the triangles around the held vertices changed: re-test them against their neighbours.
    found = crossingsAmong(grid, next, triangles, around->around(moved), stop);
  }
  return held;
}

} // namespace shrinkwrap
