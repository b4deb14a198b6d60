// Algorithm 1 by pieces: several processes (MPI ranks) each compute a slab of planes of
// one lattice, so memory and time per process follow its slab, and together they give the field of
// the whole grid, node for node. Every process holds the whole surface. Each computes the band and
// the x and y closest-point passes of its planes alone (they need nothing from other planes, given
// a few planes of band around the slab); the z pass needs each column's sites from every plane, and
// the processes send each other only the sites that can be nearest to another slab's nodes (a few
// per column, ClosestPointSweep.h). The sign regions are flooded per slab and joined across the
// slab borders, their votes added, before any side is decided (SignVotes.h).
#ifndef ShrinkWrap_SlabDistance_h
#define ShrinkWrap_SlabDistance_h

#include "Distance/SignedDistance.h"

#include <vector>

namespace shrinkwrap
{

// Every process's message, in rank order, one after the other in one buffer.
struct Messages
{
  std::vector<char> bytes;
  std::vector<std::size_t> offsets; // where each process's message starts, and the end
  std::size_t count() const { return this->offsets.empty() ? 0 : this->offsets.size() - 1; }
  const char* data(std::size_t r) const { return this->bytes.data() + this->offsets[r]; }
  std::size_t length(std::size_t r) const { return this->offsets[r + 1] - this->offsets[r]; }
};

// What the processes computing one lattice's slabs say to each other.
class SlabExchange
{
public:
  virtual ~SlabExchange() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Every process's bytes to every process. A collective call: every process makes the same calls
  // in the same order.
  virtual Messages allGather(const std::vector<char>& mine) const = 0;
};

// Fills `distance` (the nodes of planes first .. last of `whole`, x fastest) with the signed
// distance to the source, equal to computeSignedDistance's on the whole lattice at these nodes, up
// to rounding. Collective: every process of `exchange` calls it with the same lattice, settings and
// surface, and its own planes (empty ones too: last < first). The processes' planes must cover the
// grid; a process may compute planes another one computes too (ghost planes). Fails (on every
// process alike) if the planes leave a gap, or the settings ask for the Eikonal sweep (iterative
// over the whole grid). Aborting on one process aborts all: `result.completed` false.
Status computeSlabSignedDistance(const DistanceSource& source, const GridLattice& whole, int first,
  int last, const SignedDistanceSettings& settings, const SlabExchange& exchange, float* distance,
  SignedDistanceResult& result, const Progress& progress = {});

// What Mesh Signed Distance measures, by pieces: the soup's triangles (signed as settings ask), the
// points (unsigned), or both (unsigned), as computeSignedDistance, computePointDistance and
// computeUnionDistance do on the whole grid.
Status computeSlabDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& whole, int first, int last, const SignedDistanceSettings& settings,
  const SlabExchange& exchange, float* distance, SignedDistanceResult& result,
  const Progress& progress = {});

// Whether every process says yes (collective).
bool everyProcess(const SlabExchange& exchange, bool yes);

} // namespace shrinkwrap

#endif
