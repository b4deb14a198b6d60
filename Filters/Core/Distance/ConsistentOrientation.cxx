#include "Distance/ConsistentOrientation.h"
#include "Distance/SoupEdges.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace shrinkwrap
{

namespace
{
double area(const TriangleSoup& soup, int t)
{
  const auto& tri = soup.triangles[t];
  const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
  return 0.5 * (b - a).cross(c - a).norm();
}

// A triangle's neighbours across edges shared by exactly two triangles (at most one per edge), and
// whether the two run that edge the same way (then one of them is flipped against the other).
struct Neighbours
{
  std::array<std::pair<int, bool>, 3> across;
  int count = 0;
};

LargeVector<Neighbours> manifoldNeighbours(const TriangleSoup& soup)
{
  // Degenerate triangles have no orientation to pass on: a flip through one would turn everything
  // beyond it.
  const EdgeUses uses = edgeUses(soup, [&](int t) { return !unitNormal(soup, t).isZero(); });
  LargeVector<Neighbours> neighbours(soup.triangles.size());
  forEachEdge(uses, [&](std::size_t first, std::size_t last) {
    if (last - first == 2)
    {
      const EdgeUse &a = uses[first], &b = uses[first + 1];
      // A kept triangle has three distinct edges, so three neighbours at most.
      Neighbours &na = neighbours[a.triangle], &nb = neighbours[b.triangle];
      na.across[na.count++] = { b.triangle, a.forward == b.forward };
      nb.across[nb.count++] = { a.triangle, a.forward == b.forward };
    }
  });
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
      const double a = area(welded, t);
      total += a;
      flippedArea += flip[t] ? a : 0;
      for (int k = 0; k < neighbours[t].count; ++k)
      {
        const auto [u, same] = neighbours[t].across[k];
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
