#include "Distance/SoupEdges.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shrinkwrap
{

TriangleSoup weldDuplicatePoints(const TriangleSoup& soup)
{
  // Sort point ids lexicographically by coordinates; equal neighbours share one new id.
  const int n = static_cast<int>(soup.points.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const Vec3 &p = soup.points[a], &q = soup.points[b];
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3);
  };
  std::sort(order.begin(), order.end(), less);

  TriangleSoup welded;
  std::vector<int> newId(n);
  for (int k = 0; k < n; ++k)
  {
    if (k == 0 || soup.points[order[k]] != soup.points[order[k - 1]])
    {
      welded.points.push_back(soup.points[order[k]]);
    }
    newId[order[k]] = static_cast<int>(welded.points.size()) - 1;
  }
  welded.triangles.reserve(soup.triangles.size());
  for (const auto& t : soup.triangles)
  {
    const std::array<int, 3> w = { newId[t[0]], newId[t[1]], newId[t[2]] };
    // A triangle that repeats a point is a segment; it is kept for distances, which it still has.
    welded.triangles.push_back(w);
  }
  return welded;
}

long long dropRepeatedTriangles(TriangleSoup& welded, std::vector<int>* kept)
{
  const int n = static_cast<int>(welded.triangles.size());
  // Each triangle's sorted corners and index, sorted: repeats follow their first (lowest index).
  struct Key
  {
    std::array<int, 3> corners;
    int triangle;
    bool operator<(const Key& o) const
    {
      return corners != o.corners ? corners < o.corners : triangle < o.triangle;
    }
  };
  std::vector<Key> keys(n);
  for (int t = 0; t < n; ++t)
  {
    keys[t] = { welded.triangles[t], t };
    std::sort(keys[t].corners.begin(), keys[t].corners.end());
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> repeated(n, 0);
  long long dropped = 0;
  for (int k = 1; k < n; ++k)
  {
    const std::array<int, 3>& c = keys[k].corners;
    // Only proper triangles: a segment's repeats mean nothing of sides.
    if (c[0] != c[1] && c[1] != c[2] && c == keys[k - 1].corners)
    {
      repeated[keys[k].triangle] = 1;
      ++dropped;
    }
  }
  if (dropped > 0)
  {
    std::vector<std::array<int, 3>> remaining;
    remaining.reserve(n - dropped);
    for (int t = 0; t < n; ++t)
    {
      if (!repeated[t])
      {
        remaining.push_back(welded.triangles[t]);
        if (kept)
        {
          kept->push_back(t);
        }
      }
    }
    welded.triangles.swap(remaining);
  }
  return dropped;
}

Vec3 unitNormal(const TriangleSoup& soup, int triangle)
{
  const auto& tri = soup.triangles[triangle];
  const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
  const Vec3 n = (b - a).cross(c - a);
  const double longest =
    std::max({ (b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm() });
  const double len = n.norm();
  return len > 1e-9 * longest ? Vec3(n / len) : Vec3::Zero();
}

EdgeUses edgeUses(const TriangleSoup& soup, const std::function<bool(int)>& keep)
{
  // Counted into runs by the edge's lower id, then each short run sorted by its higher id: the
  // uses of an edge come in the order of their triangles.
  std::vector<int> start(soup.points.size() + 1, 0);
  const auto lowerOf = [&](const std::array<int, 3>& tri, int e) {
    return std::min(tri[e], tri[(e + 1) % 3]);
  };
  std::vector<char> kept(soup.triangles.size(), 1);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    kept[t] = !keep || keep(static_cast<int>(t));
    for (int e = 0; kept[t] && e < 3; ++e)
    {
      ++start[lowerOf(soup.triangles[t], e) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  EdgeUses uses(start.back());
  std::vector<int> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& tri = soup.triangles[t];
    for (int e = 0; kept[t] && e < 3; ++e)
    {
      const auto i = static_cast<std::uint64_t>(tri[e]),
                 j = static_cast<std::uint64_t>(tri[(e + 1) % 3]);
      uses[next[lowerOf(tri, e)]++] = { (std::min(i, j) << 32) | std::max(i, j),
        static_cast<int>(t), e, i < j };
    }
  }
  const auto byKey = [](const EdgeUse& a, const EdgeUse& b) { return a.key < b.key; };
  for (std::size_t p = 0; p + 1 < start.size(); ++p)
  {
    if (start[p + 1] - start[p] > 32) // a fan's apex
    {
      std::stable_sort(uses.begin() + start[p], uses.begin() + start[p + 1], byKey);
      continue;
    }
    for (int k = start[p] + 1; k < start[p + 1]; ++k) // insertion: a vertex's few edges
    {
      const EdgeUse use = uses[k];
      int at = k;
      for (; at > start[p] && uses[at - 1].key > use.key; --at)
      {
        uses[at] = uses[at - 1];
      }
      uses[at] = use;
    }
  }
  return uses;
}

} // namespace shrinkwrap
