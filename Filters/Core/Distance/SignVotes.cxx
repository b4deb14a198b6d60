#include "Distance/SignVotes.h"
#include "Common/Parallel.h"

namespace shrinkwrap
{

namespace
{
// Scanline flood fill from seed over nodes in state `from`, relabelled `to`: a stack of x-runs
// ("spans") rather than of nodes, so each run is claimed at once and every node is read a few times
// in memory order. visit(m) sees every 6-neighbour m of the region's nodes, for the votes. Only
// planes kFirst .. kLast are flooded (a slab's own; the planes around them are visited only), and
// claimed(row, k, x0, x1) hears of every run.
template <typename Visit, typename Claimed>
long long flood(const GridLattice& lattice, std::uint8_t* state,
  const std::vector<std::int64_t>& seeds, std::uint8_t from, std::uint8_t to, int kFirst, int kLast,
  Visit&& visit, Claimed&& claimed)
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
    claimed(row, k, x0, x1);
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
      const bool inside = r[1] >= kFirst && r[1] <= kLast;
      for (int x = span.x0; x <= span.x1; ++x)
      {
        visit(row + x);
        if (inside && state[row + x] == from)
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

template <typename Visit>
long long flood(const GridLattice& lattice, std::uint8_t* state,
  const std::vector<std::int64_t>& seeds, std::uint8_t from, std::uint8_t to, Visit&& visit)
{
  return flood(lattice, state, seeds, from, to, 0, lattice.dims[2] - 1, visit,
    [](std::int64_t, int, int, int) {});
}
} // namespace

namespace
{
// The grid nodes outside `inner`, a box of node indices with at least one node to spare on every
// side: one connected shell of off-band nodes. They are labelled Outside row by row (in planes
// kFirst .. kLast, a slab's), and the nodes on the faces of `inner` (in those planes) returned as
// seeds of the same region.
std::vector<std::int64_t> labelShell(const GridLattice& lattice, const std::array<int, 6>& inner,
  std::uint8_t* state, int kFirst, int kLast)
{
  const auto& d = lattice.dims;
  parallelFor(kFirst, kLast + 1, [&](int b, int e) {
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
  std::array<int, 6> box = inner;
  box[4] = std::max(inner[4], kFirst);
  box[5] = std::min(inner[5], kLast);
  forEachFaceNode(lattice, box, [&](std::int64_t n) {
    const auto c = lattice.coordinates(n);
    if (c[0] == inner[0] || c[0] == inner[1] || c[1] == inner[2] || c[1] == inner[3] ||
      c[2] == inner[4] || c[2] == inner[5]) // a face of the inner box, not where the slab cuts it
    {
      seeds.push_back(n);
    }
  });
  return seeds;
}
} // namespace

SignVotes signRegions(const GridLattice& lattice, bool cornerIsOutside,
  const std::array<int, 6>& bandExtent, std::uint8_t* state, const Progress& progress,
  bool& aborted)
{
  SignVotes votes;
  aborted = false;
  const auto& d = lattice.dims;
  const std::int64_t total = lattice.nodeCount();
  long long labelled = 0;

  // Regions: the outside shell first (when the band leaves room around it), then every region
  // reachable from a node not yet labelled.
  std::array<int, 6> inner;
  const bool shell = outsideShell(d, cornerIsOutside, bandExtent, inner);
  std::vector<std::int64_t> seeds;
  if (shell)
  {
    seeds = labelShell(lattice, inner, state, 0, d[2] - 1);
    labelled = total -
      static_cast<long long>(inner[1] - inner[0] + 1) * (inner[3] - inner[2] + 1) *
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
    invertBandSigns(state, total);
  }
  return votes;
}

bool outsideShell(const std::array<int, 3>& dims, bool cornerIsOutside,
  const std::array<int, 6>& bandExtent, std::array<int, 6>& inner)
{
  inner = { bandExtent[0] - 1, bandExtent[1] + 1, bandExtent[2] - 1, bandExtent[3] + 1,
    bandExtent[4] - 1, bandExtent[5] + 1 };
  return cornerIsOutside && inner[0] > 0 && inner[2] > 0 && inner[4] > 0 &&
    inner[1] < dims[0] - 1 && inner[3] < dims[1] - 1 && inner[5] < dims[2] - 1;
}

SlabRegions floodSlabRegions(const GridLattice& lattice, int ownedFirst, int ownedLast,
  const std::vector<int>& labelledPlanes, const std::array<int, 6>* shell, std::uint8_t* state,
  const Progress& progress, bool& aborted)
{
  SlabRegions regions;
  aborted = false;
  const auto& d = lattice.dims;
  const std::int64_t plane = static_cast<std::int64_t>(d[0]) * d[1];
  regions.planes = labelledPlanes;
  regions.labels.assign(labelledPlanes.size() * plane, -1);
  std::vector<int> slot(d[2], -1); // where a plane's labels are kept
  for (std::size_t p = 0; p < labelledPlanes.size(); ++p)
  {
    slot[labelledPlanes[p]] = static_cast<int>(p);
  }
  const long long total = (ownedLast - ownedFirst + 1) * plane;
  long long labelled = 0;
  // One region from the given seeds (the first node of the seeds, or of the slab, stands for it).
  auto addRegion = [&](const std::vector<std::int64_t>& seeds) {
    const auto id = static_cast<std::int32_t>(regions.seed.size());
    long long outside = 0, inside = 0;
    labelled += flood(
      lattice, state, seeds, Unvisited, Outside, ownedFirst, ownedLast,
      [&](std::int64_t m) {
        outside += state[m] == BandOutside;
        inside += state[m] == BandInside;
      },
      [&](std::int64_t row, int kr, int x0, int x1) {
        if (slot[kr] >= 0)
        {
          std::int32_t* labels = regions.labels.data() + slot[kr] * plane + (row - kr * plane);
          std::fill(labels + x0, labels + x1 + 1, id);
        }
      });
    regions.seed.push_back(seeds.empty() ? ownedFirst * plane : seeds[0]);
    regions.inside.push_back(inside);
    regions.outside.push_back(outside);
    return progress.report(static_cast<double>(labelled) / total);
  };
  if (shell)
  {
    // Region 0: the outside shell, labelled without a flood (as signRegions), and what its faces
    // reach.
    const std::vector<std::int64_t> seeds =
      labelShell(lattice, *shell, state, ownedFirst, ownedLast);
    const auto& in = *shell;
    for (std::size_t p = 0; p < labelledPlanes.size(); ++p)
    {
      const int k = labelledPlanes[p];
      for (int j = 0; j < d[1]; ++j)
      {
        for (int i = 0; i < d[0]; ++i)
        {
          if (i < in[0] || i > in[1] || j < in[2] || j > in[3] || k < in[4] || k > in[5])
          {
            regions.labels[p * plane + i + static_cast<std::int64_t>(j) * d[0]] = 0;
          }
        }
      }
    }
    labelled += total -
      static_cast<long long>(in[1] - in[0] + 1) * (in[3] - in[2] + 1) *
        std::max(0, std::min(in[5], ownedLast) - std::max(in[4], ownedFirst) + 1);
    if (!addRegion(seeds))
    {
      aborted = true;
      return regions;
    }
    regions.seed[0] = -1; // the shell is outside by definition: never relabelled
  }
  for (int k = ownedFirst; k <= ownedLast; ++k)
  {
    for (std::int64_t n = k * plane; n < (k + 1) * plane; ++n)
    {
      if (state[n] == Unvisited && !addRegion(std::vector<std::int64_t>(1, n)))
      {
        aborted = true;
        return regions;
      }
    }
  }
  return regions;
}

void labelSlabRegions(const GridLattice& lattice, int ownedFirst, int ownedLast,
  const SlabRegions& regions, const std::vector<char>& isInside, std::uint8_t* state)
{
  for (std::size_t r = 0; r < regions.seed.size(); ++r)
  {
    if (isInside[r] && regions.seed[r] >= 0)
    {
      flood(
        lattice, state, std::vector<std::int64_t>(1, regions.seed[r]), Outside, Inside, ownedFirst,
        ownedLast, [](std::int64_t) {}, [](std::int64_t, int, int, int) {});
    }
  }
}

void applySigns(const std::uint8_t* state, std::int64_t count, bool isSigned, float* distance)
{
  if (!isSigned)
  {
    return;
  }
  parallelFor(0, count, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t n = b; n < e; ++n)
    {
      if (state[n] == Inside || state[n] == BandInside)
      {
        distance[n] = -distance[n];
      }
    }
  });
}

void invertBandSigns(std::uint8_t* state, std::int64_t count)
{
  parallelFor(0, count, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t n = b; n < e; ++n)
    {
      state[n] =
        state[n] == BandInside ? BandOutside : (state[n] == BandOutside ? BandInside : state[n]);
    }
  });
}

} // namespace shrinkwrap
