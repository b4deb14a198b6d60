#include "Distance/SlabDistance.h"

#include "Distance/ClosestPointSweep.h"
#include "Distance/DistanceBand.h"
#include "Distance/PointSource.h"
#include "Distance/UnionSource.h"
#include "Distance/SignVotes.h"
#include "Distance/WindingSign.h"

#include <algorithm>
#include <cstring>
#include <numeric>

namespace shrinkwrap
{

namespace
{
// Messages: plain values and vectors of them, in the order they are read.
struct Writer
{
  std::vector<char> bytes = std::vector<char>(1, 0); // byte 0: whether the sender stopped

  template <typename T>
  void put(const T& value)
  {
    const char* p = reinterpret_cast<const char*>(&value);
    this->bytes.insert(this->bytes.end(), p, p + sizeof(T));
  }
  template <typename T>
  void put(const std::vector<T>& values)
  {
    this->put(static_cast<std::uint64_t>(values.size()));
    const char* p = reinterpret_cast<const char*>(values.data());
    this->bytes.insert(this->bytes.end(), p, p + values.size() * sizeof(T));
  }
};

struct Reader
{
  const char* bytes; // a message (byte 0: whether its sender stopped)
  std::size_t at = 1;

  template <typename T>
  T get()
  {
    T value;
    std::memcpy(&value, this->bytes + this->at, sizeof(T));
    this->at += sizeof(T);
    return value;
  }
  template <typename T>
  std::vector<T> getVector()
  {
    std::vector<T> values(this->get<std::uint64_t>());
    if (!values.empty()) // (an empty vector's data() may be null, which memcpy may not take)
    {
      std::memcpy(values.data(), this->bytes + this->at, values.size() * sizeof(T));
    }
    this->at += values.size() * sizeof(T);
    return values;
  }
};

// One collective round: every process's message, in rank order; false if any process stopped.
bool exchangeRound(const SlabExchange& exchange, bool stopped, Writer& message, Messages& all)
{
  message.bytes[0] = stopped ? 1 : 0;
  all = exchange.allGather(message.bytes);
  message = Writer();
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    if (all.length(r) == 0 || all.data(r)[0])
    {
      return false;
    }
  }
  return true;
}

struct PlaneRange
{
  int first = 0, last = -1;
  bool empty() const { return this->last < this->first; }
  bool holds(int k) const { return k >= this->first && k <= this->last; }
};

// Who owns which planes: in order of first plane, each process takes its planes not yet taken. Fails
// if a plane is left to nobody.
bool ownPlanes(const std::vector<PlaneRange>& computed, int planes, std::vector<PlaneRange>& owned)
{
  std::vector<int> order(computed.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return computed[a].first < computed[b].first; });
  owned.assign(computed.size(), PlaneRange());
  int next = 0;
  for (int r : order)
  {
    if (computed[r].empty())
    {
      continue;
    }
    if (computed[r].first > next)
    {
      return false;
    }
    owned[r] = { next, computed[r].last };
    next = std::max(next, computed[r].last + 1);
  }
  return next == planes;
}

// The planes that the other processes compute, as disjoint ascending ranges.
std::vector<std::array<int, 2>> othersPlanes(const std::vector<PlaneRange>& computed, int rank)
{
  std::vector<std::array<int, 2>> ranges;
  for (std::size_t r = 0; r < computed.size(); ++r)
  {
    if (static_cast<int>(r) != rank && !computed[r].empty())
    {
      ranges.push_back({ computed[r].first, computed[r].last });
    }
  }
  std::sort(ranges.begin(), ranges.end());
  std::vector<std::array<int, 2>> merged;
  for (const auto& r : ranges)
  {
    if (!merged.empty() && r[0] <= merged.back()[1] + 1)
    {
      merged.back()[1] = std::max(merged.back()[1], r[1]);
    }
    else
    {
      merged.push_back(r);
    }
  }
  return merged;
}

// Union-find over the regions of all slabs.
struct Regions
{
  std::vector<std::int64_t> parent;
  std::int64_t find(std::int64_t a)
  {
    while (this->parent[a] != a)
    {
      a = this->parent[a] = this->parent[this->parent[a]];
    }
    return a;
  }
  void join(std::int64_t a, std::int64_t b)
  {
    a = this->find(a);
    b = this->find(b);
    if (a != b)
    {
      this->parent[std::max(a, b)] = std::min(a, b);
    }
  }
};

// What every process learnt of the sign regions (round 2), and the sides it decides: the same on
// every process.
struct RegionSides
{
  std::vector<std::int64_t> firstRegion;            // per process: the global id of its region 0
  std::vector<std::vector<int>> planes;             // per process: its labelled planes
  std::vector<std::vector<std::int32_t>> labels;    // per process: their nodes' regions
  Regions regions;
  std::vector<char> inside; // per root
  SignVotes votes;

  // The region (root) of node n of whole-grid plane k, owned by process `owner`; -1 for a band node.
  std::int64_t regionAt(int owner, int k, std::int64_t n)
  {
    const auto& p = this->planes[owner];
    const auto slot = std::find(p.begin(), p.end(), k) - p.begin();
    if (slot == static_cast<std::ptrdiff_t>(p.size()))
    {
      return -1;
    }
    const std::int32_t label = this->labels[owner][slot * this->planeSize + n];
    return label < 0 ? -1 : this->regions.find(this->firstRegion[owner] + label);
  }
  std::int64_t planeSize = 0;
};

RegionSides decideSides(const Messages& all, const std::vector<PlaneRange>& owned,
  std::int64_t planeSize, bool cornerIsOutside)
{
  RegionSides sides;
  sides.planeSize = planeSize;
  const std::size_t n = all.count();
  std::vector<long long> inside, outside;
  sides.firstRegion.resize(n);
  for (std::size_t r = 0; r < n; ++r)
  {
    Reader in{ all.data(r) };
    sides.firstRegion[r] = static_cast<std::int64_t>(inside.size());
    const auto in_ = in.getVector<long long>(), out_ = in.getVector<long long>();
    inside.insert(inside.end(), in_.begin(), in_.end());
    outside.insert(outside.end(), out_.begin(), out_.end());
    sides.planes.push_back(in.getVector<int>());
    sides.labels.push_back(in.getVector<std::int32_t>());
  }
  sides.regions.parent.resize(inside.size());
  std::iota(sides.regions.parent.begin(), sides.regions.parent.end(), 0);
  // Regions that meet across a slab border are one.
  for (std::size_t a = 0; a < n; ++a)
  {
    for (std::size_t pa = 0; pa < sides.planes[a].size(); ++pa)
    {
      const int k = sides.planes[a][pa];
      for (std::size_t b = 0; b < n; ++b)
      {
        const auto& pb = sides.planes[b];
        const auto slot = std::find(pb.begin(), pb.end(), k + 1) - pb.begin();
        if (b == a || !owned[a].holds(k) || slot == static_cast<std::ptrdiff_t>(pb.size()))
        {
          continue;
        }
        const std::int32_t* la = sides.labels[a].data() + pa * planeSize;
        const std::int32_t* lb = sides.labels[b].data() + slot * planeSize;
        for (std::int64_t m = 0; m < planeSize; ++m)
        {
          if (la[m] >= 0 && lb[m] >= 0)
          {
            sides.regions.join(sides.firstRegion[a] + la[m], sides.firstRegion[b] + lb[m]);
          }
        }
      }
    }
  }
  std::vector<long long> in(inside.size(), 0), out(inside.size(), 0);
  for (std::size_t g = 0; g < inside.size(); ++g)
  {
    const std::int64_t root = sides.regions.find(static_cast<std::int64_t>(g));
    in[root] += inside[g];
    out[root] += outside[g];
  }
  // The corner region (outside by definition when the mesh lies inside the grid), as SignVotes.cxx.
  std::int64_t corner = -1;
  for (std::size_t r = 0; r < n && cornerIsOutside; ++r)
  {
    if (owned[r].holds(0))
    {
      corner = sides.regionAt(static_cast<int>(r), 0, 0);
    }
  }
  sides.votes.inverted = corner >= 0 && in[corner] > out[corner];
  sides.inside.assign(inside.size(), 0);
  for (std::size_t g = 0; g < inside.size(); ++g)
  {
    if (sides.regions.parent[g] != static_cast<std::int64_t>(g))
    {
      continue;
    }
    sides.inside[g] = static_cast<std::int64_t>(g) != corner && ((in[g] > out[g]) != sides.votes.inverted);
    ++sides.votes.regions;
    sides.votes.agreeing += std::max(in[g], out[g]);
    sides.votes.disagreeing += std::min(in[g], out[g]);
  }
  return sides;
}

} // namespace

Status computeSlabSignedDistance(const DistanceSource& source, const GridLattice& whole, int first, int last,
  const SignedDistanceSettings& settings, const SlabExchange& exchange, float* distance,
  SignedDistanceResult& result, const Progress& progress)
{
  result = SignedDistanceResult();
  if (settings.sweep != SweepMethod::ClosestPoint)
  {
    return Status::failure("the Eikonal sweep cannot be computed by pieces");
  }
  const int nz = whole.dims[2];
  const std::int64_t planeSize = static_cast<std::int64_t>(whole.dims[0]) * whole.dims[1];
  const PlaneRange mine{ std::max(first, 0), std::min(last, nz - 1) };

  // Round 1: who computes which planes, and who owns them.
  Messages all;
  Writer ranges;
  ranges.put(mine.first);
  ranges.put(mine.last);
  exchangeRound(exchange, false, ranges, all);
  std::vector<PlaneRange> computed, owned;
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    Reader in{ all.data(r) };
    const int f = in.get<int>();
    computed.push_back({ f, in.get<int>() });
  }
  if (!ownPlanes(computed, nz, owned))
  {
    return Status::failure("the pieces leave planes of the grid to no process");
  }
  const int rank = exchange.rank();
  const PlaneRange own = owned[rank];

  // The band, in the planes around this slab too: the band of a plane depends on the cells of the
  // planes next to it (and bandLayers more), and the votes of the slab's regions on the plane
  // beyond each side.
  const int halo = settings.bandLayers + 2;
  const PlaneRange outer{ std::max(0, mine.first - halo), std::min(nz - 1, mine.last + halo) };
  const GridLattice outerLattice = planesOf(whole, outer.first, outer.last);
  const GridLattice slab = planesOf(whole, mine.first, mine.last);
  const std::int64_t slabStart = (mine.first - outer.first) * planeSize; // outer index of the slab's node 0
  const Box grid = whole.bounds();
  const Box surface = source.bounds();
  const bool meshInsideGrid = strictlyInside(surface, grid);
  bool stopped = false;
  std::vector<std::uint8_t> state;
  DistanceBand band;
  if (!mine.empty())
  {
    std::vector<std::int64_t> cells;
    stopped = !source.outline(outerLattice, progress.stage(0.05, 0.2), cells);
    state.assign(outerLattice.nodeCount(), Unvisited);
    std::array<bool, 6> faces = allFaces(!meshInsideGrid);
    faces[4] = faces[4] && outer.first == 0;
    faces[5] = faces[5] && outer.last == nz - 1;
    std::vector<std::int64_t> nodes = bandNodes(outerLattice, cells, settings.bandLayers, faces, state.data());
    // Exact distances where they are used: the slab's planes and the plane beyond each side.
    const std::int64_t from = std::max(0, mine.first - 1 - outer.first) * planeSize,
                       to = (std::min(outer.last, mine.last + 1) - outer.first + 1) * planeSize;
    nodes.erase(std::remove_if(nodes.begin(), nodes.end(), [&](std::int64_t n) { return n < from || n >= to; }),
      nodes.end());
    stopped = stopped ||
      !computeBand(source, outerLattice, std::move(nodes), bandSearchRadius(whole, settings.bandLayers),
        onSurfaceDistance(whole), progress.stage(0.2, 0.45), band, state.data());
  }

  // Round 2: the sign regions, flooded per slab, joined across the borders, decided together. The
  // nodes outside the box around the whole band are one region (the outside), without a flood.
  bool needWinding = false;
  if (settings.computeSign)
  {
    std::array<int, 6> extent = nodeExtent(outerLattice, band.nodes);
    extent[4] = band.nodes.empty() ? nz : extent[4] + outer.first; // in whole-grid planes
    extent[5] += band.nodes.empty() ? 0 : outer.first;
    Writer bandBox;
    bandBox.put(extent);
    if (!exchangeRound(exchange, stopped, bandBox, all))
    {
      return {};
    }
    for (std::size_t r = 0; r < all.count(); ++r)
    {
      Reader in{ all.data(r) };
      const auto e = in.get<std::array<int, 6>>();
      for (int a = 0; a < 3; ++a)
      {
        extent[2 * a] = std::min(extent[2 * a], e[2 * a]);
        extent[2 * a + 1] = std::max(extent[2 * a + 1], e[2 * a + 1]);
      }
    }
    std::array<int, 6> shell;
    const bool withShell = outsideShell(whole.dims, meshInsideGrid, extent, shell);
    shell[4] -= outer.first; // in the outer lattice's planes
    shell[5] -= outer.first;
    SlabRegions regions;
    std::vector<int> labelled; // whole-grid planes: the owned planes next to or inside other slabs
    for (int k = own.first; k <= own.last; ++k)
    {
      bool wanted = k == own.first || k == own.last;
      for (std::size_t r = 0; r < computed.size(); ++r)
      {
        wanted = wanted || (static_cast<int>(r) != rank && computed[r].holds(k));
      }
      if (wanted)
      {
        labelled.push_back(k - outer.first);
      }
    }
    if (!stopped && !own.empty())
    {
      regions = floodSlabRegions(outerLattice, own.first - outer.first, own.last - outer.first, labelled,
        withShell ? &shell : nullptr, state.data(), progress.stage(0.45, 0.55), stopped);
    }
    for (int& k : regions.planes)
    {
      k += outer.first;
    }
    Writer message;
    message.put(regions.inside);
    message.put(regions.outside);
    message.put(regions.planes);
    message.put(regions.labels);
    if (!exchangeRound(exchange, stopped, message, all))
    {
      return {};
    }
    RegionSides sides = decideSides(all, owned, planeSize, meshInsideGrid);
    std::vector<char> isInside(regions.seed.size());
    for (std::size_t r = 0; r < isInside.size(); ++r)
    {
      isInside[r] = sides.inside[sides.regions.find(sides.firstRegion[rank] + static_cast<std::int64_t>(r))];
    }
    if (!own.empty())
    {
      labelSlabRegions(outerLattice, own.first - outer.first, own.last - outer.first, regions, isInside, state.data());
    }
    // Planes this process computes but others own: their regions' sides from the owners' labels.
    for (int k = mine.first; k <= mine.last; ++k)
    {
      if (own.holds(k))
      {
        continue;
      }
      const int owner = static_cast<int>(std::find_if(owned.begin(), owned.end(), [&](const PlaneRange& o) {
        return o.holds(k);
      }) - owned.begin());
      std::uint8_t* planeState = state.data() + (k - outer.first) * planeSize;
      for (std::int64_t n = 0; n < planeSize; ++n)
      {
        if (planeState[n] == Unvisited)
        {
          const std::int64_t root = sides.regionAt(owner, k, n);
          planeState[n] = root >= 0 && sides.inside[root] ? Inside : Outside;
        }
      }
    }
    if (sides.votes.inverted)
    {
      invertBandSigns(state.data(), static_cast<std::int64_t>(state.size()));
    }
    result.signDisagreements = sides.votes.disagreeing;
    result.invertedOrientation = sides.votes.inverted;
    result.isSigned = sides.votes.consistent();
    result.signMethod = result.isSigned ? SignMethod::Votes : SignMethod::None;
    needWinding = !result.isSigned && settings.windingNumber && !source.sidesConfirmed().empty();
  }

  // Round 3: the x and y passes alone, the z pass with the other slabs' winners of each column.
  std::vector<std::int32_t> site(slab.nodeCount(), -1);
  std::vector<Vec3> siteNormals = needWinding ? trustedNormals(source, band) : std::vector<Vec3>();
  for (std::size_t k = 0; k < band.nodes.size(); ++k)
  {
    const std::int64_t n = band.nodes[k] - slabStart;
    if (n >= 0 && n < slab.nodeCount())
    {
      site[n] = static_cast<std::int32_t>(k);
    }
  }
  const auto bandSize = static_cast<long long>(band.nodes.size());
  std::vector<Vec3> sitePoints = std::move(band.closest);
  band = DistanceBand(); // the rest of the band is done with: its memory goes to the passes
  const SlabPlanes planes{ whole, mine.first, mine.last, own.first, own.last };
  ColumnSites winners;
  if (!stopped && !mine.empty())
  {
    stopped = !sweepClosestPointsInPlanes(slab, sitePoints, site.data(), progress.stage(0.55, 0.75));
  }
  if (!stopped && !own.empty())
  {
    winners = columnWinners(planes, othersPlanes(computed, rank), sitePoints, site.data());
  }
  Writer message;
  message.put(winners.start);
  auto winning = [&](const std::vector<Vec3>& of) {
    std::vector<Vec3> values(winners.sites.size());
    std::transform(winners.sites.begin(), winners.sites.end(), values.begin(), [&](std::int32_t s) { return of[s]; });
    return values;
  };
  message.put(winning(sitePoints));
  message.put(needWinding ? winning(siteNormals) : std::vector<Vec3>());
  winners = ColumnSites();
  if (!exchangeRound(exchange, stopped, message, all))
  {
    return {};
  }
  if (!mine.empty())
  {
    ColumnSites others;
    others.start.assign(planeSize + 1, 0);
    std::vector<std::vector<std::int64_t>> starts(all.count());
    std::vector<std::int32_t> firstSite(all.count());
    for (std::size_t r = 0; r < all.count(); ++r)
    {
      Reader in{ all.data(r) };
      starts[r] = in.getVector<std::int64_t>();
      if (static_cast<int>(r) == rank || starts[r].empty())
      {
        starts[r].clear();
        continue;
      }
      firstSite[r] = static_cast<std::int32_t>(sitePoints.size());
      const auto p = in.getVector<Vec3>();
      const auto n = in.getVector<Vec3>();
      sitePoints.insert(sitePoints.end(), p.begin(), p.end());
      siteNormals.insert(siteNormals.end(), n.begin(), n.end());
      for (std::int64_t c = 0; c < planeSize; ++c)
      {
        others.start[c + 1] += starts[r][c + 1] - starts[r][c];
      }
    }
    std::partial_sum(others.start.begin(), others.start.end(), others.start.begin());
    others.sites.resize(others.start.back());
    std::vector<std::int64_t> fill(others.start.begin(), others.start.end() - 1);
    all = Messages(); // read: its memory goes to the z pass
    for (std::size_t r = 0; r < starts.size(); ++r)
    {
      for (std::int64_t c = 0; c < static_cast<std::int64_t>(starts[r].size()) - 1; ++c)
      {
        for (std::int64_t s = starts[r][c]; s < starts[r][c + 1]; ++s)
        {
          others.sites[fill[c]++] = firstSite[r] + static_cast<std::int32_t>(s);
        }
      }
    }
    sweepColumns(planes, sitePoints, others, site.data(), distance);
    stopped = !progress.report(0.85);
  }

  // Round 4: the winding number where the votes disagreed, and the counts of all slabs.
  WindingSignResult winding;
  if (needWinding && !stopped && !mine.empty())
  {
    winding = signByWindingNumber(
      source, slab, sitePoints, siteNormals, site.data(), state.data() + slabStart, progress.stage(0.85, 0.98));
    stopped = !winding.completed;
  }
  Writer counts;
  counts.put(bandSize);
  counts.put(winding.evaluated);
  counts.put(winding.inside);
  if (!exchangeRound(exchange, stopped, counts, all))
  {
    return {};
  }
  long long inside = 0;
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    Reader in{ all.data(r) };
    result.bandNodes += in.get<long long>();
    result.windingEvaluations += in.get<long long>();
    inside += in.get<long long>();
  }
  if (needWinding)
  {
    const auto& confirmed = source.sidesConfirmed();
    result.unconfirmedTriangles = std::count(confirmed.begin(), confirmed.end(), 0);
    result.invertedOrientation = false;
    result.isSigned = inside > 0;
    result.signMethod = result.isSigned ? SignMethod::WindingNumber : SignMethod::None;
  }
  if (!mine.empty())
  {
    applySigns(state.data() + slabStart, slab.nodeCount(), result.isSigned, distance);
  }
  result.completed = progress.report(1);
  return {};
}

Status computeSlabDistance(const TriangleSoup& soup, const std::vector<Vec3>& points, const GridLattice& whole,
  int first, int last, const SignedDistanceSettings& settings, const SlabExchange& exchange, float* distance,
  SignedDistanceResult& result, const Progress& progress)
{
  SignedDistanceSettings unsignedSettings = settings;
  unsignedSettings.computeSign = false; // points have no inside
  if (points.empty())
  {
    const TriangleSource source(soup);
    const Status status =
      computeSlabSignedDistance(source, whole, first, last, settings, exchange, distance, result, progress);
    result.boundaryEdges = source.boundaryEdges();
    result.nonManifoldEdges = source.nonManifoldEdges();
    result.reorientedTriangles = source.reorientedTriangles();
    return status;
  }
  const Status status = soup.triangles.empty()
    ? computeSlabSignedDistance(PointSource(points), whole, first, last, unsignedSettings, exchange, distance, result, progress)
    : computeSlabSignedDistance(UnionSource({ std::make_shared<const TriangleSource>(soup), std::make_shared<const PointSource>(points) }),
        whole, first, last, unsignedSettings, exchange, distance, result, progress);
  result.points = static_cast<long long>(points.size());
  result.triangles = static_cast<long long>(soup.triangles.size());
  return status;
}

bool everyProcess(const SlabExchange& exchange, bool yes)
{
  const Messages all = exchange.allGather(std::vector<char>(1, yes ? 1 : 0));
  bool every = true;
  for (std::size_t r = 0; r < all.count(); ++r)
  {
    every = every && all.length(r) > 0 && all.data(r)[0];
  }
  return every;
}

} // namespace shrinkwrap
