#include "SignFill.h"

#include <vtkSMPTools.h>

namespace shrinkwrap
{

namespace
{
// Calls f(neighbour) for the 6-neighbours of node n inside the grid.
template <typename F>
void forNeighbours(const GridLattice& lattice, std::int64_t n, F&& f)
{
  const auto& d = lattice.dims;
  const std::int64_t sy = d[0], sz = sy * d[1];
  const int i = static_cast<int>(n % sy), j = static_cast<int>((n / sy) % d[1]), k = static_cast<int>(n / sz);
  if (i > 0) f(n - 1);
  if (i + 1 < d[0]) f(n + 1);
  if (j > 0) f(n - sy);
  if (j + 1 < d[1]) f(n + sy);
  if (k > 0) f(n - sz);
  if (k + 1 < d[2]) f(n + sz);
}

// Breadth first from seed over nodes in state `from`, relabelled `to`, one wavefront at a time (the
// fronts stay about as large as a grid face, never the whole grid). visit(m) sees every neighbour.
template <typename Visit>
long long flood(const GridLattice& lattice, std::uint8_t* state, std::int64_t seed, std::uint8_t from,
  std::uint8_t to, Visit&& visit)
{
  std::vector<std::int64_t> front(1, seed), next;
  state[seed] = to;
  long long count = 1;
  while (!front.empty())
  {
    next.clear();
    for (std::int64_t n : front)
    {
      forNeighbours(lattice, n, [&](std::int64_t m) {
        visit(m);
        if (state[m] == from)
        {
          state[m] = to;
          next.push_back(m);
        }
      });
    }
    count += static_cast<long long>(next.size());
    front.swap(next);
  }
  return count;
}
} // namespace

SignVotes signRegions(const GridLattice& lattice, bool cornerIsOutside, std::uint8_t* state,
  const Progress& progress, bool& aborted)
{
  SignVotes votes;
  aborted = false;
  const std::int64_t total = lattice.nodeCount();
  long long labelled = 0;
  for (std::int64_t seed = 0; seed < total; ++seed)
  {
    if (state[seed] != Unvisited)
    {
      continue;
    }
    long long outside = 0, inside = 0;
    labelled += flood(lattice, state, seed, Unvisited, Outside, [&](std::int64_t m) {
      outside += state[m] == BandOutside;
      inside += state[m] == BandInside;
    });
    if (seed == 0 && cornerIsOutside && inside > outside)
    {
      votes.inverted = true;
    }
    if ((inside > outside) != votes.inverted)
    {
      flood(lattice, state, seed, Outside, Inside, [](std::int64_t) {});
    }
    ++votes.regions;
    votes.agreeing += std::max(inside, outside);
    votes.disagreeing += std::min(inside, outside);
    if (!progress.report(static_cast<double>(labelled) / total))
    {
      aborted = true;
      return votes;
    }
  }
  if (votes.inverted)
  {
    vtkSMPTools::For(0, total, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t n = b; n < e; ++n)
      {
        state[n] = state[n] == BandInside ? BandOutside : (state[n] == BandOutside ? BandInside : state[n]);
      }
    });
  }
  return votes;
}

} // namespace shrinkwrap
