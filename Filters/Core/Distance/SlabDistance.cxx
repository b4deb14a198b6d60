#include "Distance/SlabDistance.h"

#include "Distance/ClosestPointSweep.h"
#include "Distance/DistanceBand.h"
#include "Distance/PointSource.h"
#include "Distance/SignVotes.h"
#include "Distance/UnionSource.h"
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

// Who owns which planes: in order of first plane, each process takes its planes not yet taken.
// Fails if a plane is left to nobody.
bool ownPlanes(const std::vector<PlaneRange>& computed, int planes, std::vector<PlaneRange>& owned)
{
  std::vector<int> order(computed.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](int a, int b) { return computed[a].first < computed[b].first; });
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
  std::vector<std::int64_t> firstRegion;         // per process: the global id of its region 0
  std::vector<std::vector<int>> planes;          // per process: its labelled planes
  std::vector<std::vector<std::int32_t>> labels; // per process: their nodes' regions
  Regions regions;
  std::vector<char> inside; // per root
  SignVotes votes;

  // The region (root) of node n of whole-grid plane k, owned by process `owner`; -1 for a band
  // node.
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
    sides.inside[g] =
      static_cast<std::int64_t>(g) != corner && ((in[g] > out[g]) != sides.votes.inverted);
    ++sides.votes.regions;
    sides.votes.agreeing += std::max(in[g], out[g]);
    sides.votes.disagreeing += std::min(in[g], out[g]);
  }
  return sides;
}

} // namespace

namespace
{
// One rank's slab, computed in rounds with the other ranks: the rounds' shared state.
class SlabRun
{
public:
  SlabRun(const DistanceSource& source, const GridLattice& whole, int first, int last,
    const SignedDistanceSettings& settings, const SlabExchange& exchange, const Progress& progress)
    : Source(source)
    , Whole(whole)
    , Settings(settings)
    , Exchange(exchange)
    , Report(progress)
    , Planes(whole.dims[2])
    , PlaneSize(static_cast<std::int64_t>(whole.dims[0]) * whole.dims[1])
    , Mine{ std::max(first, 0), std::min(last, whole.dims[2] - 1) }
    , Rank(exchange.rank())
  {
  }

  Status sharePlanes();                                       // round 1
  void bandOfSlab();                                          // this slab's outline and band
  bool decideSigns(SignedDistanceResult& result);             // round 2; false: a rank stopped
  bool sweep(float* distance);                                // round 3
  bool finish(SignedDistanceResult& result, float* distance); // round 4

private:
  void signOthersPlanes(RegionSides& sides);
  void readColumnSites(ColumnSites& others);

  const DistanceSource& Source;
  const GridLattice& Whole;
  const SignedDistanceSettings& Settings;
  const SlabExchange& Exchange;
  const Progress& Report;
  const int Planes;
  const std::int64_t PlaneSize;
  const PlaneRange Mine;
  const int Rank;
  std::vector<PlaneRange> Computed, Owned; // by rank
  PlaneRange Own{ 0, -1 };
  PlaneRange Outer{ 0, -1 }; // Mine with the planes around it that its band and votes need
  GridLattice OuterLattice, Slab;
  std::int64_t SlabStart = 0; // the outer lattice's index of the slab's node 0
  bool MeshInsideGrid = false;
  bool Stopped = false;
  Messages All;
  std::vector<std::uint8_t> State;
  DistanceBand Band;
  bool NeedWinding = false;
  long long BandSize = 0;
  std::vector<std::int32_t> Site;
  SiteList SitePoints, SiteNormals;
};

// Round 1: who computes which planes, and who owns them.
Status SlabRun::sharePlanes()
{
  Writer ranges;
  ranges.put(this->Mine.first);
  ranges.put(this->Mine.last);
  exchangeRound(this->Exchange, false, ranges, this->All);
  for (std::size_t r = 0; r < this->All.count(); ++r)
  {
    Reader in{ this->All.data(r) };
    const int f = in.get<int>();
    this->Computed.push_back({ f, in.get<int>() });
  }
  if (!ownPlanes(this->Computed, this->Planes, this->Owned))
  {
    return Status::failure("the pieces leave planes of the grid to no process");
  }
  this->Own = this->Owned[this->Rank];
  // The band in the planes around this slab too: the band of a plane depends on the cells of the
  // planes next to it (and bandLayers more), and the votes of the slab's regions on the plane
  // beyond each side.
  const int halo = this->Settings.bandLayers + 2;
  this->Outer = { std::max(0, this->Mine.first - halo),
    std::min(this->Planes - 1, this->Mine.last + halo) };
  this->OuterLattice = planesOf(this->Whole, this->Outer.first, this->Outer.last);
  this->Slab = planesOf(this->Whole, this->Mine.first, this->Mine.last);
  this->SlabStart = (this->Mine.first - this->Outer.first) * this->PlaneSize;
  this->MeshInsideGrid = strictlyInside(this->Source.bounds(), this->Whole.bounds());
  return {};
}

void SlabRun::bandOfSlab()
{
  if (this->Mine.empty())
  {
    return;
  }
  IndexList cells;
  this->Stopped = !this->Source.outline(this->OuterLattice, this->Report.stage(0.05, 0.2), cells);
  this->State.assign(this->OuterLattice.nodeCount(), Unvisited);
  std::array<bool, 6> faces = allFaces(!this->MeshInsideGrid);
  faces[4] = faces[4] && this->Outer.first == 0;
  faces[5] = faces[5] && this->Outer.last == this->Planes - 1;
  IndexList nodes =
    bandNodes(this->OuterLattice, cells, this->Settings.bandLayers, faces, this->State.data());
  // Exact distances where they are used: the slab's planes and the plane beyond each side.
  const std::int64_t from = std::max(0, this->Mine.first - 1 - this->Outer.first) * this->PlaneSize;
  const std::int64_t to =
    (std::min(this->Outer.last, this->Mine.last + 1) - this->Outer.first + 1) * this->PlaneSize;
  nodes.erase(
    std::remove_if(nodes.begin(), nodes.end(), [&](std::int64_t n) { return n < from || n >= to; }),
    nodes.end());
  this->Stopped = this->Stopped ||
    !computeBand(this->Source, this->OuterLattice, std::move(nodes),
      bandSearchRadius(this->Whole, this->Settings.bandLayers), onSurfaceDistance(this->Whole),
      this->Report.stage(0.2, 0.45), this->Band, this->State.data());
}

// Round 2: the sign regions, flooded per slab, joined across the borders, decided together. The
// nodes outside the box around the whole band are one region (the outside), without a flood.
bool SlabRun::decideSigns(SignedDistanceResult& result)
{
  const int shift = this->Outer.first; // whole-grid planes from the outer lattice's
  std::array<int, 6> extent = nodeExtent(this->OuterLattice, this->Band.nodes);
  extent[4] = this->Band.nodes.empty() ? this->Planes : extent[4] + shift;
  extent[5] += this->Band.nodes.empty() ? 0 : shift;
  Writer bandBox;
  bandBox.put(extent);
  if (!exchangeRound(this->Exchange, this->Stopped, bandBox, this->All))
  {
    return false;
  }
  for (std::size_t r = 0; r < this->All.count(); ++r)
  {
    Reader in{ this->All.data(r) };
    const auto e = in.get<std::array<int, 6>>();
    for (int a = 0; a < 3; ++a)
    {
      extent[2 * a] = std::min(extent[2 * a], e[2 * a]);
      extent[2 * a + 1] = std::max(extent[2 * a + 1], e[2 * a + 1]);
    }
  }
  std::array<int, 6> shell;
  const bool withShell = outsideShell(this->Whole.dims, this->MeshInsideGrid, extent, shell);
  shell[4] -= shift;
  shell[5] -= shift;
  SlabRegions regions;
  std::vector<int> labelled; // the owned planes next to or inside other slabs (outer planes)
  for (int k = this->Own.first; k <= this->Own.last; ++k)
  {
    bool wanted = k == this->Own.first || k == this->Own.last;
    for (std::size_t r = 0; r < this->Computed.size(); ++r)
    {
      wanted = wanted || (static_cast<int>(r) != this->Rank && this->Computed[r].holds(k));
    }
    if (wanted)
    {
      labelled.push_back(k - shift);
    }
  }
  if (!this->Stopped && !this->Own.empty())
  {
    regions = floodSlabRegions(this->OuterLattice, this->Own.first - shift, this->Own.last - shift,
      labelled, withShell ? &shell : nullptr, this->State.data(), this->Report.stage(0.45, 0.55),
      this->Stopped);
  }
  for (int& k : regions.planes)
  {
    k += shift;
  }
  Writer message;
  message.put(regions.inside);
  message.put(regions.outside);
  message.put(regions.planes);
  message.put(regions.labels);
  if (!exchangeRound(this->Exchange, this->Stopped, message, this->All))
  {
    return false;
  }
  RegionSides sides = decideSides(this->All, this->Owned, this->PlaneSize, this->MeshInsideGrid);
  std::vector<char> isInside(regions.seed.size());
  for (std::size_t r = 0; r < isInside.size(); ++r)
  {
    const std::int64_t region = sides.firstRegion[this->Rank] + static_cast<std::int64_t>(r);
    isInside[r] = sides.inside[sides.regions.find(region)];
  }
  if (!this->Own.empty())
  {
    labelSlabRegions(this->OuterLattice, this->Own.first - shift, this->Own.last - shift, regions,
      isInside, this->State.data());
  }
  this->signOthersPlanes(sides);
  if (sides.votes.inverted)
  {
    invertBandSigns(this->State.data(), static_cast<std::int64_t>(this->State.size()));
  }
  result.signDisagreements = sides.votes.disagreeing;
  result.invertedOrientation = sides.votes.inverted;
  result.isSigned = sides.votes.consistent();
  result.signMethod = result.isSigned ? SignMethod::Votes : SignMethod::None;
  this->NeedWinding =
    !result.isSigned && this->Settings.windingNumber && !this->Source.sidesConfirmed().empty();
  return true;
}

// Planes this process computes but others own: their regions' sides from the owners' labels.
void SlabRun::signOthersPlanes(RegionSides& sides)
{
  for (int k = this->Mine.first; k <= this->Mine.last; ++k)
  {
    if (this->Own.holds(k))
    {
      continue;
    }
    const auto owner = static_cast<int>(std::find_if(this->Owned.begin(), this->Owned.end(),
                                          [&](const PlaneRange& o) { return o.holds(k); }) -
      this->Owned.begin());
    std::uint8_t* planeState = this->State.data() + (k - this->Outer.first) * this->PlaneSize;
    for (std::int64_t n = 0; n < this->PlaneSize; ++n)
    {
      if (planeState[n] == Unvisited)
      {
        const std::int64_t root = sides.regionAt(owner, k, n);
        planeState[n] = root >= 0 && sides.inside[root] ? Inside : Outside;
      }
    }
  }
}

// Round 3: the x and y passes alone, the z pass with the other slabs' winners of each column.
bool SlabRun::sweep(float* distance)
{
  this->Site.assign(this->Slab.nodeCount(), -1);
  if (this->NeedWinding)
  {
    this->SiteNormals = trustedNormals(this->Source, this->Band);
  }
  for (std::size_t k = 0; k < this->Band.nodes.size(); ++k)
  {
    const std::int64_t n = this->Band.nodes[k] - this->SlabStart;
    if (n >= 0 && n < this->Slab.nodeCount())
    {
      this->Site[n] = static_cast<std::int32_t>(k);
    }
  }
  this->BandSize = static_cast<long long>(this->Band.nodes.size());
  this->SitePoints = std::move(this->Band.closest);
  this->Band = DistanceBand(); // the rest of the band is done with: its memory goes to the passes
  const SlabPlanes planes{ this->Whole, this->Mine.first, this->Mine.last, this->Own.first,
    this->Own.last };
  ColumnSites winners;
  if (!this->Stopped && !this->Mine.empty())
  {
    this->Stopped = !sweepClosestPointsInPlanes(
      this->Slab, this->SitePoints, this->Site.data(), this->Report.stage(0.55, 0.75));
  }
  if (!this->Stopped && !this->Own.empty())
  {
    winners = columnWinners(
      planes, othersPlanes(this->Computed, this->Rank), this->SitePoints, this->Site.data());
  }
  Writer message;
  message.put(winners.start);
  auto winning = [&](const SiteList& of) {
    std::vector<Vec3> values(winners.sites.size());
    std::transform(winners.sites.begin(), winners.sites.end(), values.begin(),
      [&](std::int32_t s) { return of[s]; });
    return values;
  };
  message.put(winning(this->SitePoints));
  message.put(this->NeedWinding ? winning(this->SiteNormals) : std::vector<Vec3>());
  winners = ColumnSites();
  if (!exchangeRound(this->Exchange, this->Stopped, message, this->All))
  {
    return false;
  }
  if (!this->Mine.empty())
  {
    ColumnSites others;
    this->readColumnSites(others);
    sweepColumns(planes, this->SitePoints, others, this->Site.data(), distance);
    this->Stopped = !this->Report.report(0.85);
  }
  return true;
}

// The other slabs' winners of each column (round 3's messages), appended to this slab's sites.
void SlabRun::readColumnSites(ColumnSites& others)
{
  const std::size_t ranks = this->All.count();
  others.start.assign(this->PlaneSize + 1, 0);
  std::vector<std::vector<std::int64_t>> starts(ranks);
  std::vector<std::int32_t> firstSite(ranks);
  for (std::size_t r = 0; r < ranks; ++r)
  {
    Reader in{ this->All.data(r) };
    starts[r] = in.getVector<std::int64_t>();
    if (static_cast<int>(r) == this->Rank || starts[r].empty())
    {
      starts[r].clear();
      continue;
    }
    firstSite[r] = static_cast<std::int32_t>(this->SitePoints.size());
    const auto p = in.getVector<Vec3>();
    const auto n = in.getVector<Vec3>();
    this->SitePoints.insert(this->SitePoints.end(), p.begin(), p.end());
    this->SiteNormals.insert(this->SiteNormals.end(), n.begin(), n.end());
    for (std::int64_t c = 0; c < this->PlaneSize; ++c)
    {
      others.start[c + 1] += starts[r][c + 1] - starts[r][c];
    }
  }
  std::partial_sum(others.start.begin(), others.start.end(), others.start.begin());
  others.sites.resize(others.start.back());
  std::vector<std::int64_t> fill(others.start.begin(), others.start.end() - 1);
  this->All = Messages(); // read: its memory goes to the z pass
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
}

// Round 4: the winding number where the votes disagreed, and the counts of all slabs.
bool SlabRun::finish(SignedDistanceResult& result, float* distance)
{
  WindingSignResult winding;
  if (this->NeedWinding && !this->Stopped && !this->Mine.empty())
  {
    winding = signByWindingNumber(this->Source, this->Slab, this->SitePoints, this->SiteNormals,
      this->Site.data(), this->State.data() + this->SlabStart, this->Report.stage(0.85, 0.98));
    this->Stopped = !winding.completed;
  }
  Writer counts;
  counts.put(this->BandSize);
  counts.put(winding.evaluated);
  counts.put(winding.inside);
  if (!exchangeRound(this->Exchange, this->Stopped, counts, this->All))
  {
    return false;
  }
  long long inside = 0;
  for (std::size_t r = 0; r < this->All.count(); ++r)
  {
    Reader in{ this->All.data(r) };
    result.bandNodes += in.get<long long>();
    result.windingEvaluations += in.get<long long>();
    inside += in.get<long long>();
  }
  if (this->NeedWinding)
  {
    const auto& confirmed = this->Source.sidesConfirmed();
    result.unconfirmedTriangles = std::count(confirmed.begin(), confirmed.end(), 0);
    result.invertedOrientation = false;
    result.isSigned = inside > 0;
    result.signMethod = result.isSigned ? SignMethod::WindingNumber : SignMethod::None;
  }
  if (!this->Mine.empty())
  {
    applySigns(
      this->State.data() + this->SlabStart, this->Slab.nodeCount(), result.isSigned, distance);
  }
  return true;
}
} // namespace

Status computeSlabSignedDistance(const DistanceSource& source, const GridLattice& whole, int first,
  int last, const SignedDistanceSettings& settings, const SlabExchange& exchange, float* distance,
  SignedDistanceResult& result, const Progress& progress)
{
  result = SignedDistanceResult();
  if (settings.sweep != SweepMethod::ClosestPoint)
  {
    return Status::failure("the Eikonal sweep cannot be computed by pieces");
  }
  SlabRun run(source, whole, first, last, settings, exchange, progress);
  if (Status shared = run.sharePlanes(); !shared)
  {
    return shared;
  }
  run.bandOfSlab();
  // A round that finds a rank stopped (aborted) ends every rank's run there, not completed.
  if ((settings.computeSign && !run.decideSigns(result)) || !run.sweep(distance) ||
    !run.finish(result, distance))
  {
    return {};
  }
  result.completed = progress.report(1);
  return {};
}

Status computeSlabDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& whole, int first, int last, const SignedDistanceSettings& settings,
  const SlabExchange& exchange, float* distance, SignedDistanceResult& result,
  const Progress& progress)
{
  SignedDistanceSettings unsignedSettings = settings;
  unsignedSettings.computeSign = false; // points have no inside
  if (points.empty())
  {
    const TriangleSource source(soup);
    const Status status = computeSlabSignedDistance(
      source, whole, first, last, settings, exchange, distance, result, progress);
    result.boundaryEdges = source.boundaryEdges();
    result.nonManifoldEdges = source.nonManifoldEdges();
    result.reorientedTriangles = source.reorientedTriangles();
    return status;
  }
  const Status status = soup.triangles.empty()
    ? computeSlabSignedDistance(PointSource(points), whole, first, last, unsignedSettings, exchange,
        distance, result, progress)
    : computeSlabSignedDistance(UnionSource({ std::make_shared<const TriangleSource>(soup),
                                  std::make_shared<const PointSource>(points) }),
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
