#include "Surface/SurfaceMesh.h"

#include "Common/Parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <sstream>
#include <utility>

namespace shrinkwrap
{

namespace
{
// A directed edge a -> b of triangle t, whose third vertex follows b.
struct Corner
{
  int a, b, c, triangle;
};

// Corners grouped by vertex: at vertex a, triangle (a, b, c) leads from neighbour b to neighbour c.
// Bucketed by a (counting sort; each bucket is sorted by b where its fan is walked): linear time,
// as this runs again after every round of edits. `bucket` gets the bucket offsets.
Status sortCorners(int nv, const std::vector<std::array<int, 3>>& triangles,
  std::vector<Corner>& corners, std::vector<int>& bucket)
{
  const int nt = static_cast<int>(triangles.size());
  bucket.assign(nv + 1, 0);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
      if (a < 0 || a >= nv || b < 0 || b >= nv || c < 0 || c >= nv)
      {
        return Status::failure("a triangle refers to a vertex that does not exist");
      }
      if (a == b || b == c || c == a)
      {
        std::ostringstream why;
        why << "triangle " << t << " repeats a vertex";
        return Status::failure(why.str());
      }
      ++bucket[a + 1];
    }
  }
  for (int v = 0; v < nv; ++v)
  {
    bucket[v + 1] += bucket[v];
  }
  corners.resize(3 * static_cast<std::size_t>(nt));
  std::vector<int> fill(bucket.begin(), bucket.end() - 1);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      corners[fill[tri[k]]++] = { tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3], t };
    }
  }
  return {};
}

// Walks the fan of vertex v, whose corners are [first, last) (sorted here by b): from neighbour b,
// the corner starting at b leads to c, which must start the next. Writes v's ring entries.
Status walkFan(int v, Corner* first, Corner* last, int* ring, int* ringTriangle)
{
  std::sort(first, last, [](const Corner& x, const Corner& y) { return x.b < y.b; });
  // Messages are made only on failure: this runs for every vertex after every round of edits.
  auto failure = [v](const char* what, int other = -1) {
    std::ostringstream why;
    why << what << v;
    if (other >= 0)
    {
      why << ", " << other << ")";
    }
    return Status::failure(why.str());
  };
  if (first == last)
  {
    return failure("a vertex belongs to no triangle: vertex ");
  }
  auto find = [&](int b) -> const Corner* {
    const Corner* it =
      std::lower_bound(first, last, b, [](const Corner& x, int key) { return x.b < key; });
    return it != last && it->b == b ? it : nullptr;
  };
  if (std::adjacent_find(
        first, last, [](const Corner& x, const Corner& y) { return x.b == y.b; }) != last)
  {
    return failure(
      "an edge is used by more than two triangles or twice in one direction at vertex ");
  }
  const Corner* corner = first;
  for (int p = 0; p < last - first; ++p)
  {
    if (p > 0 && corner->b == first->b)
    {
      return failure("its triangles form more than one fan (non-manifold) at vertex ");
    }
    ring[p] = corner->b;
    ringTriangle[p] = corner->triangle;
    const Corner* following = find(corner->c);
    if (!following)
    {
      return failure("the surface is open or inconsistently oriented at the edge (", corner->c);
    }
    corner = following;
  }
  if (corner != first)
  {
    return failure("its triangles form more than one fan (non-manifold) at vertex ");
  }
  return {};
}

std::uint64_t edgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
    static_cast<std::uint32_t>(b);
}

constexpr std::array<int, 3> kRemoved = { -1, -1, -1 };

// Directed edge -> triangle, open addressing in one array: filled with every edge of the surface on
// a round of edits' first lookup between touched vertices, so without a node allocation per edge (a
// std::unordered_map made that fill most of a step's splits' cost).
class EdgeTable
{
public:
  void reserve(std::size_t edges)
  {
    std::size_t size = 16;
    while (size < 2 * edges)
    {
      size <<= 1;
    }
    this->Slots.assign(size, { kEmpty, -1 });
    this->Used = 0;
  }
  int find(std::uint64_t key) const
  {
    if (this->Slots.empty())
    {
      return -1;
    }
    for (std::size_t s = this->first(key);; s = (s + 1) & (this->Slots.size() - 1))
    {
      if (this->Slots[s].first == key)
        return this->Slots[s].second;
      if (this->Slots[s].first == kEmpty)
        return -1;
    }
  }
  void set(std::uint64_t key, int value)
  {
    if (this->Slots.empty())
    {
      this->reserve(8);
    }
    std::size_t free = this->Slots.size();
    std::size_t s = this->first(key);
    for (;; s = (s + 1) & (this->Slots.size() - 1))
    {
      if (this->Slots[s].first == key)
      {
        this->Slots[s].second = value;
        return;
      }
      if (this->Slots[s].first == kGone && free == this->Slots.size())
        free = s;
      if (this->Slots[s].first == kEmpty)
        break;
    }
    if (free == this->Slots.size())
    {
      free = s;
      ++this->Used;
    }
    this->Slots[free] = { key, value };
    if (2 * this->Used > this->Slots.size())
    {
      this->grow();
    }
  }
  // Removes the key if it maps to value.
  void erase(std::uint64_t key, int value)
  {
    for (std::size_t s = this->first(key); !this->Slots.empty();
         s = (s + 1) & (this->Slots.size() - 1))
    {
      if (this->Slots[s].first == key)
      {
        if (this->Slots[s].second == value)
          this->Slots[s].first = kGone; // keeps the probe chains through it
        return;
      }
      if (this->Slots[s].first == kEmpty)
        return;
    }
  }

private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0), kGone = kEmpty - 1;
  std::size_t first(std::uint64_t key) const
  {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & (this->Slots.size() - 1);
  }
  void grow()
  {
    std::vector<std::pair<std::uint64_t, int>> old;
    old.swap(this->Slots);
    this->reserve(old.size());
    for (const auto& slot : old)
    {
      if (slot.first != kEmpty && slot.first != kGone)
        this->set(slot.first, slot.second);
    }
  }
  std::vector<std::pair<std::uint64_t, int>> Slots;
  std::size_t Used = 0; // slots not empty (tombstones included)
};
} // namespace

// What the edits since the last commit need: which vertices they touched (the rings of the others
// are still exact), the directed edges of the triangles the edits set, the removed vertices, and
// the surface as committed, to restore if the commit fails.
struct SurfaceMesh::EditState
{
  std::vector<char> touched; // per committed vertex
  EdgeTable edgeTriangle;    // the directed edges of the triangles the edits set
  std::vector<char> removedVertex;
  int removals = 0; // vertices and triangles removed
  std::vector<std::array<int, 3>> committedTriangles;
  std::vector<Vec3> committedPoints;
  VertexProperties committedProperties;
};

SurfaceMesh::SurfaceMesh() = default;
SurfaceMesh::SurfaceMesh(SurfaceMesh&&) noexcept = default;
SurfaceMesh& SurfaceMesh::operator=(SurfaceMesh&&) noexcept = default;
SurfaceMesh::~SurfaceMesh() = default;

SurfaceMesh::SurfaceMesh(const SurfaceMesh& other)
  : Triangles(other.Triangles)
  , Points(other.Points)
  , Properties(other.Properties)
  , RingStart(other.RingStart)
  , Ring(other.Ring)
  , RingTriangle(other.RingTriangle)
  , Edits(other.Edits ? std::make_unique<EditState>(*other.Edits) : nullptr)
{
}

SurfaceMesh& SurfaceMesh::operator=(const SurfaceMesh& other)
{
  if (this != &other)
  {
    SurfaceMesh copy(other);
    *this = std::move(copy);
  }
  return *this;
}

Status SurfaceMesh::build(const std::vector<Vec3>& points,
  const std::vector<std::array<int, 3>>& triangles, SurfaceMesh& mesh)
{
  if (points.empty() || triangles.empty())
  {
    return Status::failure("the surface is empty");
  }
  for (const auto& p : points)
  {
    if (!p.allFinite())
    {
      return Status::failure("the surface has NaN or infinite coordinates");
    }
  }
  SurfaceMesh built;
  built.Points = points;
  built.Triangles = triangles;
  if (Status status = built.connect(); !status)
  {
    return status;
  }
  mesh = std::move(built);
  return {};
}

Status SurfaceMesh::connect()
{
  const int nv = static_cast<int>(this->Points.size());
  std::vector<Corner> corners;
  std::vector<int> bucket;
  if (Status status = sortCorners(nv, this->Triangles, corners, bucket); !status)
  {
    return status;
  }
  // Every vertex's corners are as many as its ring entries; the walk checks they form one fan. The
  // vertices are walked in parallel; a failure is reported for the first vertex that fails, as a
  // sequential walk would.
  this->RingStart = bucket;
  this->Ring.resize(corners.size());
  this->RingTriangle.resize(corners.size());
  auto walk = [&](int v) {
    return walkFan(v, corners.data() + bucket[v], corners.data() + bucket[v + 1],
      this->Ring.data() + bucket[v], this->RingTriangle.data() + bucket[v]);
  };
  std::atomic<int> firstFailing{ nv };
  parallelFor(0, nv, 1024, [&](Index b, Index e) {
    for (int v = static_cast<int>(b); v < static_cast<int>(e); ++v)
    {
      if (!walk(v))
      {
        int seen = firstFailing.load();
        while (v < seen && !firstFailing.compare_exchange_weak(seen, v))
        {
        }
        return;
      }
    }
  });
  if (firstFailing < nv)
  {
    return walk(firstFailing);
  }
  this->Properties.resize(nv);
  return {};
}

int SurfaceMesh::ringEntry(int i, int j) const
{
  for (int p = this->RingStart[i]; p < this->RingStart[i + 1]; ++p)
  {
    if (this->Ring[p] == j)
    {
      return p;
    }
  }
  return -1;
}

void SurfaceMesh::beginEdit()
{
  if (this->Edits)
  {
    return;
  }
  this->Edits = std::make_unique<EditState>();
  EditState& e = *this->Edits;
  e.committedTriangles = this->Triangles;
  e.committedPoints = this->Points;
  e.committedProperties = this->Properties;
  e.removedVertex.assign(this->Points.size(), 0);
  e.touched.assign(this->Points.size(), 0);
}

// From the ring of an end the edits have not touched (exact since the commit); else from the map of
// the directed edges of the triangles the edits set (kept current by every edit), else from a
// committed ring whose triangle still holds the edge.
int SurfaceMesh::triangleOf(int a, int b) const
{
  EditState& e = *this->Edits;
  const int committed = static_cast<int>(e.touched.size());
  if (a < committed && !e.touched[a])
  {
    const int p = this->ringEntry(a, b);
    return p < 0 ? -1 : this->RingTriangle[p];
  }
  if (b < committed && !e.touched[b])
  {
    const int q = this->ringEntry(b, a); // triangle (b, x, a) holds a -> b
    return q < 0 ? -1 : this->RingTriangle[this->previous(b, q)];
  }
  const int set = e.edgeTriangle.find(edgeKey(a, b));
  if (set >= 0)
  {
    return set;
  }
  const auto holds = [&](int t) {
    const auto& v = this->Triangles[t];
    return (v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b);
  };
  if (a < committed)
  {
    const int p = this->ringEntry(a, b);
    if (p >= 0 && holds(this->RingTriangle[p]))
    {
      return this->RingTriangle[p];
    }
  }
  return -1; // a new vertex's triangles were all set by the edits
}

void SurfaceMesh::setTriangle(int t, const std::array<int, 3>& triangle)
{
  EditState& e = *this->Edits;
  const std::array<int, 3> old = t < this->triangleCount() ? this->Triangles[t] : kRemoved;
  for (const auto& v : { old, triangle })
  {
    for (int k = 0; k < 3 && v[0] >= 0; ++k)
    {
      if (v[k] < static_cast<int>(e.touched.size()))
      {
        e.touched[v[k]] = 1;
      }
    }
  }
  for (int k = 0; k < 3 && old[0] >= 0; ++k)
  {
    e.edgeTriangle.erase(edgeKey(old[k], old[(k + 1) % 3]), t);
  }
  if (t == this->triangleCount())
  {
    this->Triangles.push_back(triangle);
  }
  this->Triangles[t] = triangle;
  for (int k = 0; k < 3 && triangle[0] >= 0; ++k)
  {
    e.edgeTriangle.set(edgeKey(triangle[k], triangle[(k + 1) % 3]), t);
  }
}

namespace
{
// The vertex of triangle t after a, and the one after that.
int after(const std::array<int, 3>& t, int a)
{
  return t[0] == a ? t[1] : (t[1] == a ? t[2] : t[0]);
}

// Triangle t with vertex `from` replaced by `to`, in the same slot (so the same rotation).
std::array<int, 3> replaced(std::array<int, 3> t, int from, int to)
{
  for (int& v : t)
  {
    v = v == from ? to : v;
  }
  return t;
}
} // namespace

int SurfaceMesh::split(int a, int b, double t)
{
  this->beginEdit();
  const int ab = this->triangleOf(a, b), ba = this->triangleOf(b, a);
  if (ab < 0 || ba < 0)
  {
    return -1;
  }
  const int c = after(this->Triangles[ab], b), d = after(this->Triangles[ba], a);
  const int m = static_cast<int>(this->Points.size());
  this->Points.push_back((1 - t) * this->Points[a] + t * this->Points[b]);
  this->Properties.resize(m);
  this->Properties.appendBetween(a, b, t);
  this->Edits->removedVertex.push_back(0);
  // (a, b, c) -> (a, m, c) + (m, b, c); (b, a, d) -> (b, m, d) + (m, a, d).
  this->setTriangle(ab, replaced(this->Triangles[ab], b, m));
  this->setTriangle(this->triangleCount(), { m, b, c });
  this->setTriangle(ba, replaced(this->Triangles[ba], a, m));
  this->setTriangle(this->triangleCount(), { m, a, d });
  return m;
}

bool SurfaceMesh::flip(int a, int b)
{
  this->beginEdit();
  const int ab = this->triangleOf(a, b), ba = this->triangleOf(b, a);
  if (ab < 0 || ba < 0)
  {
    return false;
  }
  const int c = after(this->Triangles[ab], b), d = after(this->Triangles[ba], a);
  if (c == d || this->triangleOf(c, d) >= 0 || this->triangleOf(d, c) >= 0)
  {
    return false;
  }
  this->setTriangle(ab, { a, d, c });
  this->setTriangle(ba, { d, b, c });
  return true;
}

bool SurfaceMesh::collapse(int keep, int gone, const Vec3& position)
{
  this->beginEdit();
  const int first = this->triangleOf(gone, keep);
  if (first < 0 || this->triangleOf(keep, gone) < 0)
  {
    return false;
  }
  // Around `gone`: triangle (gone, x, y) is followed by the one with edge (gone, y).
  std::vector<int> fan;
  for (int t = first; fan.empty() || t != first;
       t = this->triangleOf(gone, after(this->Triangles[t], after(this->Triangles[t], gone))))
  {
    if (t < 0 || fan.size() > this->Triangles.size())
    {
      return false;
    }
    fan.push_back(t);
  }
  for (int t : fan)
  {
    const auto& v = this->Triangles[t];
    const bool onEdge = v[0] == keep || v[1] == keep || v[2] == keep;
    this->setTriangle(t, onEdge ? kRemoved : replaced(v, gone, keep));
  }
  this->Points[keep] = position;
  this->Edits->removedVertex[gone] = 1;
  this->Edits->removals += 3;
  return true;
}

int SurfaceMesh::removePart(int v)
{
  if (v < 0 || v >= this->vertexCount())
  {
    return 0;
  }
  this->beginEdit();
  std::vector<int> part = { v };
  this->Edits->removedVertex[v] = 1;
  ++this->Edits->removals;
  for (std::size_t k = 0; k < part.size(); ++k)
  {
    const int i = part[k];
    for (int p = this->ringBegin(i); p < this->ringEnd(i); ++p)
    {
      const int t = this->ringTriangle(p);
      if (this->Triangles[t][0] >= 0)
      {
        this->setTriangle(t, kRemoved);
        ++this->Edits->removals;
      }
      if (const int j = this->ring(p); !this->Edits->removedVertex[j])
      {
        this->Edits->removedVertex[j] = 1;
        ++this->Edits->removals;
        part.push_back(j);
      }
    }
  }
  return static_cast<int>(part.size());
}

Status SurfaceMesh::commit()
{
  if (!this->Edits)
  {
    return {};
  }
  std::unique_ptr<EditState> edits = std::move(this->Edits);
  Renumbering renumbered = this->compact(edits->removedVertex);
  Status status = this->reconnect(edits->touched, renumbered);
  if (!status)
  {
    this->Triangles = std::move(edits->committedTriangles);
    this->Points = std::move(edits->committedPoints);
    this->Properties = std::move(edits->committedProperties);
    this->connect();
  }
  return status;
}

// Drops removed vertices and triangles; the others keep their order.
SurfaceMesh::Renumbering SurfaceMesh::compact(const std::vector<char>& removedVertex)
{
  const int nv = static_cast<int>(this->Points.size());
  Renumbering r;
  r.vertex.assign(nv, -1);
  int kept = 0;
  for (int v = 0; v < nv; ++v)
  {
    if (!removedVertex[v])
    {
      r.vertex[v] = kept++;
      this->Points[r.vertex[v]] = this->Points[v];
      this->Properties.move(v, r.vertex[v]);
    }
  }
  this->Points.resize(kept);
  this->Properties.resize(kept);
  r.triangle.assign(this->Triangles.size(), -1);
  int t = 0;
  for (std::size_t u = 0; u < this->Triangles.size(); ++u)
  {
    const auto& old = this->Triangles[u];
    if (old[0] >= 0)
    {
      r.triangle[u] = t;
      this->Triangles[t++] = { r.vertex[old[0]], r.vertex[old[1]], r.vertex[old[2]] };
    }
  }
  this->Triangles.resize(t);
  return r;
}

// The rings of vertices the edits did not touch are the committed ones, renumbered (the numbering
// keeps the order, so each still starts at its lowest neighbour, as connect() would start it); only
// the touched and new vertices' fans are walked again. A commit after a few edits thus costs a pass
// over the rings, not a sort of every corner.
Status SurfaceMesh::reconnect(const std::vector<char>& touched, const Renumbering& r)
{
  const int committed = static_cast<int>(touched.size());
  const int nv = static_cast<int>(this->Points.size());
  std::vector<int> oldOf(nv, -1);
  for (int o = 0; o < static_cast<int>(r.vertex.size()); ++o)
  {
    if (r.vertex[o] >= 0)
    {
      oldOf[r.vertex[o]] = o;
    }
  }
  std::vector<char> walk(nv); // touched or new: the fans walked again
  for (int v = 0; v < nv; ++v)
  {
    walk[v] = oldOf[v] >= committed || touched[oldOf[v]];
  }
  auto dirty = [&walk](int v) { return walk[v] != 0; };
  // The touched and new vertices' corners, bucketed by vertex.
  std::vector<int> count(nv + 1, 0);
  const int nt = this->triangleCount();
  for (const auto& tri : this->Triangles)
  {
    for (int v : tri)
    {
      if (v < 0 || v >= nv)
      {
        return this->connect(); // it reports the bad triangle
      }
      count[v + 1] += dirty(v);
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
    {
      return this->connect();
    }
  }
  std::vector<int> start(nv + 1, 0);
  for (int v = 0; v < nv; ++v)
  {
    start[v + 1] = start[v] + (dirty(v) ? count[v + 1] : this->valence(oldOf[v]));
    count[v + 1] += count[v];
  }
  std::vector<Corner> corners(count[nv]);
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = this->Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      if (dirty(tri[k]))
      {
        corners[fill[tri[k]]++] = { tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3], t };
      }
    }
  }
  std::vector<int> ring(start[nv]), ringTriangle(start[nv]);
  for (int v = 0; v < nv; ++v)
  {
    if (dirty(v))
    {
      if (Status status = walkFan(v, corners.data() + count[v], corners.data() + count[v + 1],
            ring.data() + start[v], ringTriangle.data() + start[v]);
          !status)
      {
        return status;
      }
      continue;
    }
    for (int p = this->RingStart[oldOf[v]], q = start[v]; q < start[v + 1]; ++p, ++q)
    {
      ring[q] = r.vertex[this->Ring[p]];
      ringTriangle[q] = r.triangle[this->RingTriangle[p]];
    }
  }
  this->RingStart.swap(start);
  this->Ring.swap(ring);
  this->RingTriangle.swap(ringTriangle);
  this->Properties.resize(nv);
  return {};
}

} // namespace shrinkwrap
