// Sign of Algorithm 1, line 8, by flood fill. The band (the nodes of every cell the surface
// touches) is watertight for a closed mesh, so the off-band nodes fall into connected regions
// (6-neighbours) that lie wholly inside or wholly outside. A grid edge from a band node to an
// off-band node does not cross the surface (else both ends would be band nodes), so every band node
// next to a region has the region's side: its pseudonormal sign votes for it. A closed mesh gives
// unanimous votes; a minority means that one region reaches both sides of the surface through a
// hole, and the field is unsigned. Voting needs no seed on the grid boundary, so grids that cut
// through the mesh are signed too.
#ifndef ShrinkWrap_SignVotes_h
#define ShrinkWrap_SignVotes_h

#include "Distance/DistanceBand.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shrinkwrap
{

struct SignVotes
{
  bool inverted =
    false; // the triangles face inwards: every sign was flipped to follow the geometry
  long long regions = 0;
  long long agreeing = 0;    // band-to-region grid edges whose band sign is the region's
  long long disagreeing = 0; // ... whose band sign is not
  bool consistent() const { return this->disagreeing == 0; }
};

// Labels every Unvisited node Outside or Inside by the votes of the band nodes around its region
// (no votes: Outside). With cornerIsOutside (the mesh lies inside the grid), the region of node 0
// is outside by definition: if its votes say inside, the mesh faces inwards and all signs are
// flipped. bandExtent (imin, imax, jmin, jmax, kmin, kmax of the band nodes) lets the nodes well
// away from the band be labelled without a flood. Sets aborted if the progress callback asked to
// stop.
SignVotes signRegions(const GridLattice& lattice, bool cornerIsOutside,
  const std::array<int, 6>& bandExtent, std::uint8_t* state, const Progress& progress,
  bool& aborted);

// Negates the distances of the inside nodes (band and off-band) of an unsigned field, if signed.
void applySigns(const std::uint8_t* state, std::int64_t count, bool isSigned, float* distance);

// The box of node indices around the band (bandExtent grown by a node on every side) when its
// outside is one shell of off-band nodes labelled without a flood: the mesh inside the grid
// (cornerIsOutside) and a node to spare between the box and every face of the grid. False: no
// shell.
bool outsideShell(const std::array<int, 3>& dims, bool cornerIsOutside,
  const std::array<int, 6>& bandExtent, std::array<int, 6>& inner);

// Swaps BandInside and BandOutside (a mesh facing inwards).
void invertBandSigns(std::uint8_t* state, std::int64_t count);

// The regions of one slab of planes (SlabDistance.h): its processes flood their own planes, and
// then join the regions that meet across their borders and count their votes together.
struct SlabRegions
{
  std::vector<std::int64_t> seed;         // per region: its first node
  std::vector<long long> inside, outside; // per region: its votes
  std::vector<int> planes;                // the planes whose nodes' regions are listed in labels
  std::vector<std::int32_t> labels; // per node of those planes: its region, -1 for a band node
};

// Floods the Unvisited nodes of planes ownedFirst .. ownedLast into regions (labelled Outside for
// now), counting the votes of band nodes next to them (in the planes around too: the lattice must
// hold a band plane beyond each side that has one). With `shell` (the box of node indices around
// the whole band, with a node to spare on every side, as signRegions finds it), the nodes outside
// it are region 0, the corner region, labelled without a flood. Sets aborted if progress asked to
// stop.
SlabRegions floodSlabRegions(const GridLattice& lattice, int ownedFirst, int ownedLast,
  const std::vector<int>& labelledPlanes, const std::array<int, 6>* shell, std::uint8_t* state,
  const Progress& progress, bool& aborted);
// Labels the regions whose isInside is set Inside.
void labelSlabRegions(const GridLattice& lattice, int ownedFirst, int ownedLast,
  const SlabRegions& regions, const std::vector<char>& isInside, std::uint8_t* state);

} // namespace shrinkwrap

#endif
