// A soup's edges and repeats (SoupEdges.h) and its orientation (ConsistentOrientation.h), which the
// distance's pseudonormals and sign stand on: every kept triangle's three edge uses, grouped by
// edge in ascending keys and, within an edge, in the order of the triangles, also around a fan's
// apex of many triangles; the back faces of a double-sided mesh dropped, the first of each repeat
// kept, a segment's repeat kept; the flipped faces of a closed mesh turned back.
#include "Distance/ConsistentOrientation.h"
#include "Distance/SoupEdges.h"
#include "Surface/Icosphere.h"
#include "TestUtilities.h"

#include <cmath>
#include <map>

namespace
{
using namespace shrinkwrap;

// A cone's fan: `sides` triangles around the apex (point 0) over a ring, closed by a fan at the
// ring's centre (point 1).
TriangleSoup cone(int sides)
{
  TriangleSoup soup;
  soup.points = { Vec3(0, 0, 1), Vec3(0, 0, 0) };
  for (int k = 0; k < sides; ++k)
  {
    const double a = 2 * M_PI * k / sides;
    soup.points.emplace_back(std::cos(a), std::sin(a), 0);
  }
  for (int k = 0; k < sides; ++k)
  {
    const int p = 2 + k, q = 2 + (k + 1) % sides;
    soup.triangles.push_back({ 0, p, q });
    soup.triangles.push_back({ 1, q, p });
  }
  return soup;
}

void edgesGrouped()
{
  const TriangleSoup soup = cone(40); // the apexes' runs hold 40 edges each: longer than a sort by
                                      // insertion takes
  const auto keep = [](int t) { return t % 7 != 3; };
  const EdgeUses uses = edgeUses(soup, keep);
  int kept = 0;
  for (int t = 0; t < static_cast<int>(soup.triangles.size()); ++t)
  {
    kept += keep(t);
  }
  SW_CHECK(uses.size() == 3u * kept, "three uses per kept triangle");
  // Every use names its triangle's edge, the right way round; uses sorted by key, then triangle.
  std::map<std::uint64_t, int> perEdge;
  bool named = true, ordered = true;
  for (std::size_t k = 0; k < uses.size(); ++k)
  {
    const EdgeUse& u = uses[k];
    const auto& t = soup.triangles[u.triangle];
    const std::uint64_t i = t[u.slot], j = t[(u.slot + 1) % 3];
    named = named && keep(u.triangle) && u.key == ((std::min(i, j) << 32) | std::max(i, j)) &&
      u.forward == (i < j);
    if (k > 0)
    {
      const EdgeUse& v = uses[k - 1];
      ordered = ordered && (v.key < u.key || (v.key == u.key && v.triangle < u.triangle));
    }
    ++perEdge[u.key];
  }
  SW_CHECK(named, "each use is its triangle's edge, with its direction");
  SW_CHECK(ordered, "uses ascend by edge, and by triangle within an edge");
  int runs = 0, usesInRuns = 0;
  forEachEdge(uses, [&](std::size_t first, std::size_t last) {
    ++runs;
    usesInRuns += static_cast<int>(last - first);
  });
  SW_CHECK(runs == static_cast<int>(perEdge.size()) && usesInRuns == static_cast<int>(uses.size()),
    "forEachEdge visits each edge once with all its uses");
  // A spoke of the cone is used by its two apex triangles (unless one was left out).
  SW_CHECK(perEdge.at((std::uint64_t(0) << 32) | 2) == 2, "a spoke has two uses");
}

void repeatsDropped()
{
  TriangleSoup soup = icosphere(1, Vec3::Zero(), 1);
  const int n = static_cast<int>(soup.triangles.size());
  for (int t = 0; t < n; ++t) // the back faces, as a double-sided mesh has them
  {
    const auto c = soup.triangles[t];
    soup.triangles.push_back({ c[0], c[2], c[1] });
  }
  soup.triangles.push_back(soup.triangles[5]); // a repeat the same way round
  soup.triangles.push_back({ 0, 1, 1 });       // a segment, twice: kept both times
  soup.triangles.push_back({ 1, 0, 1 });
  std::vector<int> kept;
  const long long dropped = dropRepeatedTriangles(soup, &kept);
  std::printf("repeats: %lld dropped, %zu kept\n", dropped, kept.size());
  SW_CHECK(dropped == n + 1, "every back face and the repeat dropped");
  SW_CHECK(soup.triangles.size() == static_cast<std::size_t>(n + 2),
    "the front faces and the "
    "segments remain");
  bool first = kept.size() == soup.triangles.size();
  for (int t = 0; first && t < n; ++t)
  {
    first = kept[t] == t;
  }
  SW_CHECK(first && kept[n] == 2 * n + 1 && kept[n + 1] == 2 * n + 2,
    "the first of each repeat is the one kept, in the soup's order");
  std::vector<int> none;
  TriangleSoup clean = icosphere(1, Vec3::Zero(), 1);
  SW_CHECK(dropRepeatedTriangles(clean, &none) == 0 && none.empty(), "a clean soup keeps all");
}

void flippedTurnedBack()
{
  TriangleSoup soup = icosphere(2, Vec3::Zero(), 1);
  const auto original = soup.triangles;
  int flipped = 0;
  for (std::size_t t = 0; t < soup.triangles.size(); t += 9)
  {
    std::swap(soup.triangles[t][1], soup.triangles[t][2]);
    ++flipped;
  }
  const long long turned = orientConsistently(soup);
  SW_CHECK(turned == flipped, "each flipped face is turned back, and no other");
  SW_CHECK(soup.triangles == original, "the soup is as it was before the flips");
}
} // namespace

int TestSoupEdges(int, char*[])
{
  edgesGrouped();
  repeatsDropped();
  flippedTurnedBack();
  return testing::finish("TestSoupEdges");
}
