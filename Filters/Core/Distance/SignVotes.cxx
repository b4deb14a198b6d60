#include "SignVotes.h"
#include "Parallel.h"

#include <vtkSMPTools.h>

namespace shrinkwrap
{

namespace
{
// Scanline flood fill from seed over nodes in state `from`, relabelled `to`: a stack of x-runs
// ("spans") rather than of nodes, so each run is claimed at once and every node is read a few times
// in memory order. visit(m) sees every 6-neighbour m of the region's nodes, for the votes.
template <typename Visit>
long long flood(const GridLattice& lattice, std::uint8_t* state, const std::vector<std::int64_t>& seeds,
  std::uint8_t from, std::uint8_t to, Visit&& visit)
{
  const auto& d = lattice.dims;
  const std::int64_t sy = d[0], sz = sy * d[1];
  struct Span
  {
    std::int64_t row; // index of the row's first node
    int j, k, x0, x1; // inclusive x range
  };
  // Claims the run of `from` nodes through x in the row, returns it.
  auto claim = [&](std::int64_t row, int j, int k, int x) {
    int x0 = x, x1 = x;
    while (x0 > 0 && state[row + x0 - 1] == from)
    {
      --x0;
    }
    while (x1 + 1 < d[0] && state[row + x1 + 1] == from)
    {
      ++x1;
    }
    std::fill(state + row + x0, state + row + x1 + 1, to);
    return Span{ row, j, k, x0, x1 };
  };
  std::vector<Span> stack;
  for (std::int64_t seed : seeds)
  {
    if (state[seed] == from)
    {
      const int sj = static_cast<int>((seed / sy) % d[1]), sk = static_cast<int>(seed / sz);
      stack.push_back(claim(seed - seed % sy, sj, sk, static_cast<int>(seed % sy)));
    }
  }
  long long count = 0;
  while (!stack.empty())
  {
    const Span span = stack.back();
    stack.pop_back();
    count += span.x1 - span.x0 + 1;
    if (span.x0 > 0)
    {
      visit(span.row + span.x0 - 1);
    }
    if (span.x1 + 1 < d[0])
    {
      visit(span.row + span.x1 + 1);
    }
    const int rows[4][2] = { { span.j - 1, span.k }, { span.j + 1, span.k }, { span.j, span.k - 1 },
      { span.j, span.k + 1 } };
    for (const auto& r : rows)
    {
      if (r[0] < 0 || r[0] >= d[1] || r[1] < 0 || r[1] >= d[2])
      {
        continue;
      }
      const std::int64_t row = r[0] * sy + r[1] * sz;
      for (int x = span.x0; x <= span.x1; ++x)
      {
        visit(row + x);
        if (state[row + x] == from)
        {
          // The new span's nodes are region nodes, not band nodes: nothing to visit for votes.
          const Span found = claim(row, r[0], r[1], x);
          stack.push_back(found);
          x = found.x1;
        }
      }
    }
  }
  return count;
}
} // namespace

namespace
{
// The grid nodes outside `inner`, a box of node indices with at least one node to spare on every side:
// one connected shell of off-band nodes. They are labelled Outside row by row, and the nodes on the
// faces of `inner` returned as seeds of the same region.
std::vector<std::int64_t> labelShell(
  const GridLattice& lattice, const std::array<int, 6>& inner, std::uint8_t* state)
{
  const auto& d = lattice.dims;
  parallelFor(0, d[2], [&](int b, int e) {
    for (int k = b; k < e; ++k)
    {
      for (int j = 0; j < d[1]; ++j)
      {
        std::uint8_t* row = state + lattice.index(0, j, k);
        const bool crosses = k >= inner[4] && k <= inner[5] && j >= inner[2] && j <= inner[3];
        if (!crosses)
        {
          std::fill(row, row + d[0], static_cast<std::uint8_t>(Outside));
          continue;
        }
        std::fill(row, row + inner[0], static_cast<std::uint8_t>(Outside));
        std::fill(row + inner[1] + 1, row + d[0], static_cast<std::uint8_t>(Outside));
      }
    }
  });
  std::vector<std::int64_t> seeds;
  forEachFaceNode(lattice, inner, [&](std::int64_t n) { seeds.push_back(n); });
  return seeds;
}
} // namespace

SignVotes signRegions(const GridLattice& lattice, bool cornerIsOutside, const std::array<int, 6>& bandExtent,
  std::uint8_t* state, const Progress& progress, bool& aborted)
{
  SignVotes votes;
  aborted = false;
  const auto& d = lattice.dims;
  const std::int64_t total = lattice.nodeCount();
  long long labelled = 0;

  // Regions: the outside shell first (when the band leaves room around it), then every region
  // reachable from a node not yet labelled.
  std::array<int, 6> inner = { bandExtent[0] - 1, bandExtent[1] + 1, bandExtent[2] - 1, bandExtent[3] + 1,
    bandExtent[4] - 1, bandExtent[5] + 1 };
  const bool shell = cornerIsOutside && inner[0] > 0 && inner[2] > 0 && inner[4] > 0 && inner[1] < d[0] - 1 &&
    inner[3] < d[1] - 1 && inner[5] < d[2] - 1;
  std::vector<std::int64_t> seeds;
  if (shell)
  {
    seeds = labelShell(lattice, inner, state);
    labelled = total - static_cast<long long>(inner[1] - inner[0] + 1) * (inner[3] - inner[2] + 1) *
        (inner[5] - inner[4] + 1);
  }
  else
  {
    inner = { 0, d[0] - 1, 0, d[1] - 1, 0, d[2] - 1 };
  }
  // One region from the given seeds. The corner region (outside by definition when the mesh lies
  // inside the grid) comes first: if its band votes say inside, the mesh faces inwards.
  auto signRegion = [&](const std::vector<std::int64_t>& from, bool corner) {
    long long outside = 0, inside = 0;
    labelled += flood(lattice, state, from, Unvisited, Outside, [&](std::int64_t m) {
      outside += state[m] == BandOutside;
      inside += state[m] == BandInside;
    });
    if (corner)
    {
      votes.inverted = inside > outside;
    }
    else if ((inside > outside) != votes.inverted)
    {
      flood(lattice, state, from, Outside, Inside, [](std::int64_t) {});
    }
    ++votes.regions;
    votes.agreeing += std::max(inside, outside);
    votes.disagreeing += std::min(inside, outside);
    return progress.report(static_cast<double>(labelled) / total);
  };
  if (shell || (cornerIsOutside && state[0] == Unvisited))
  {
    if (!signRegion(shell ? seeds : std::vector<std::int64_t>(1, 0), true))
    {
      aborted = true;
      return votes;
    }
  }
  for (int k = inner[4]; k <= inner[5]; ++k)
  {
    for (int j = inner[2]; j <= inner[3]; ++j)
    {
      for (int i = inner[0]; i <= inner[1]; ++i)
      {
        const std::int64_t seed = lattice.index(i, j, k);
        if (state[seed] == Unvisited && !signRegion(std::vector<std::int64_t>(1, seed), false))
        {
          aborted = true;
          return votes;
        }
      }
    }
  }
  if (votes.inverted)
  {
    parallelFor(0, total, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t n = b; n < e; ++n)
      {
        state[n] = state[n] == BandInside ? BandOutside : (state[n] == BandOutside ? BandInside : state[n]);
      }
    });
  }
  return votes;
}

} // namespace shrinkwrap
