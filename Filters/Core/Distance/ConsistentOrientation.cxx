#include "ConsistentOrientation.h"

#include <algorithm>
#include <cstdint>

namespace shrinkwrap
{

namespace
{
struct EdgeUse
{
  std::uint64_t key;
  int triangle;
  bool forward; // the triangle runs the edge from its lower to its higher point index
};

double area(const TriangleSoup& soup, int t)
{
  const auto& tri = soup.triangles[t];
  const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
  return 0.5 * (b - a).cross(c - a).norm();
}

// Whether a triangle is too thin for its normal to mean anything (a needle or a cap, as at seams).
bool degenerate(const TriangleSoup& soup, int t)
{
  const auto& tri = soup.triangles[t];
  const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
  const double longest = std::max({ (b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm() });
  return !((b - a).cross(c - a).norm() > 1e-9 * longest);
}

// Per triangle, its neighbours across edges shared by exactly two triangles, and whether the two run
// that edge the same way (then one of them is flipped against the other).
std::vector<std::vector<std::pair<int, bool>>> manifoldNeighbours(const TriangleSoup& soup)
{
  std::vector<EdgeUse> uses;
  uses.reserve(3 * soup.triangles.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    const auto& tri = soup.triangles[t];
    if (degenerate(soup, static_cast<int>(t)))
    {
      continue; // no orientation to pass on: a flip through it would turn everything beyond
    }
    for (int e = 0; e < 3; ++e)
    {
      const auto i = static_cast<std::uint64_t>(tri[e]), j = static_cast<std::uint64_t>(tri[(e + 1) % 3]);
      if (i != j)
      {
        uses.push_back({ (std::min(i, j) << 32) | std::max(i, j), static_cast<int>(t), i < j });
      }
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) { return a.key < b.key; });
  std::vector<std::vector<std::pair<int, bool>>> neighbours(soup.triangles.size());
  for (std::size_t first = 0; first < uses.size();)
  {
    std::size_t last = first;
    while (last < uses.size() && uses[last].key == uses[first].key)
    {
      ++last;
    }
    if (last - first == 2)
    {
      const EdgeUse &a = uses[first], &b = uses[first + 1];
      neighbours[a.triangle].push_back({ b.triangle, a.forward == b.forward });
      neighbours[b.triangle].push_back({ a.triangle, a.forward == b.forward });
    }
    first = last;
  }
  return neighbours;
}

} // namespace

long long orientConsistently(TriangleSoup& welded)
{
  const int nt = static_cast<int>(welded.triangles.size());
  const auto neighbours = manifoldNeighbours(welded);
  std::vector<signed char> flip(nt, -1); // -1: not reached yet
  std::vector<int> piece;
  long long flipped = 0;
  for (int seed = 0; seed < nt; ++seed)
  {
    if (flip[seed] >= 0)
    {
      continue;
    }
    // Breadth first from the seed: a neighbour running the shared edge the same way is flipped
    // relative to its parent.
    piece.assign(1, seed);
    flip[seed] = 0;
    double flippedArea = 0, total = 0;
    for (std::size_t q = 0; q < piece.size(); ++q)
    {
      const int t = piece[q];
      total += area(welded, t);
      flippedArea += flip[t] ? area(welded, t) : 0;
      for (const auto& [u, same] : neighbours[t])
      {
        if (flip[u] < 0)
        {
          flip[u] = static_cast<signed char>(flip[t] ^ same);
          piece.push_back(u);
        }
      }
    }
    // Keep the orientation most of the piece's area was given.
    const bool invert = flippedArea > 0.5 * total;
    for (int t : piece)
    {
      if (flip[t] != invert)
      {
        std::swap(welded.triangles[t][1], welded.triangles[t][2]);
        ++flipped;
      }
    }
  }
  return flipped;
}

} // namespace shrinkwrap
