// A triangle soup's points welded and its edges found: points with identical coordinates are welded
// so that the pseudonormals of shared vertices and edges can be found.
#ifndef ShrinkWrap_SoupEdges_h
#define ShrinkWrap_SoupEdges_h

#include "Common/HugePages.h"
#include "Common/TriangleSoup.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace shrinkwrap
{

// Merge points with bit-identical coordinates. The result is the same surface; only the indices
// change (a triangle that then repeats an index is kept: as a segment it still has distances).
TriangleSoup weldDuplicatePoints(const TriangleSoup& soup);
// Drops every triangle whose three point ids an earlier one has, in either orientation: the back
// faces of a double-sided mesh, whose winding numbers would cancel the front's. Returns how many;
// `kept`, if given, receives each remaining triangle's index before (left empty when none dropped).
long long dropRepeatedTriangles(TriangleSoup& welded, std::vector<int>* kept = nullptr);

// A triangle's unit normal, or zero where it is too thin for its normal to mean anything (a needle
// or a cap, as the slivers at a parametric surface's seams: their cross product is rounding noise).
Vec3 unitNormal(const TriangleSoup& soup, int triangle);

// One triangle's use of an undirected edge: the edge's two point ids in `key` (lower << 32 |
// higher), `slot` the edge in the triangle (0: corners 0-1, 1: 1-2, 2: 2-0), `forward` whether the
// triangle runs it from the lower id to the higher.
struct EdgeUse
{
  std::uint64_t key;
  int triangle;
  int slot;
  bool forward;
};

using EdgeUses = LargeVector<EdgeUse>; // megabytes for a large soup: huge pages

// The edge uses of the triangles `keep` accepts (all when empty), grouped by edge: sorted by key.
EdgeUses edgeUses(const TriangleSoup& soup, const std::function<bool(int)>& keep = {});

// f(first, last) for each edge's run [first, last) of `uses` (grouped as edgeUses gives them).
template <typename F>
void forEachEdge(const EdgeUses& uses, F&& f)
{
  for (std::size_t first = 0; first < uses.size();)
  {
    std::size_t last = first + 1;
    while (last < uses.size() && uses[last].key == uses[first].key)
    {
      ++last;
    }
    f(first, last);
    first = last;
  }
}

} // namespace shrinkwrap

#endif
