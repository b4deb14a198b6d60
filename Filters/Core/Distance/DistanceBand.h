// The band of exact distances (Algorithm 1, line 5): every node of the cells the outline found
// (Outline.h), plus optional extra layers, gets its exact distance, closest point and sign; the
// node states it leaves are those the sign votes (SignVotes.h) go on from.
#ifndef ShrinkWrap_DistanceBand_h
#define ShrinkWrap_DistanceBand_h

#include "Common/Progress.h"
#include "Distance/DistanceSource.h"
#include "Distance/GridLattice.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shrinkwrap
{

// Per-node state shared by the band and the sign fill.
enum NodeState : std::uint8_t
{
  Unvisited = 0,
  BandOnSurface = 1, // a band node on the surface (or not yet signed): no side
  BandOutside = 2,
  BandInside = 3,
  Outside = 4,
  Inside = 5
};
inline bool isBand(std::uint8_t state)
{
  return state >= BandOnSurface && state <= BandInside;
}

struct DistanceBand
{
  IndexList nodes;               // grid node indices
  SiteList closest;              // closest surface point of each band node
  LargeVector<float> distance;   // exact unsigned distance
  LargeVector<signed char> sign; // +1 outside, -1 inside, from the closest feature's pseudonormal
  LargeVector<std::array<float, 3>> normal; // the pseudonormal there (unit length)
  LargeVector<std::int32_t> element;        // the triangle the closest point lies on
  LargeVector<char> sure;                   // SourcePoint::sure: whether `sign` can be trusted
};

// Marks the nodes of the given cells (and `extraLayers` rings of 6-neighbours) as band nodes in
// state, and lists them. The nodes on the grid's faces that gridFaces names (-x, +x, -y, +y, -z,
// +z) join too: a grid that does not contain the whole mesh needs exact distances and signs there
// (a slab's own cut faces are not the grid's). Whether the surface's box lies strictly inside the
// grid's (then the grid's corner is outside).
inline bool strictlyInside(const Box& surface, const Box& grid)
{
  return (surface.min.array() > grid.min.array()).all() &&
    (surface.max.array() < grid.max.array()).all();
}
// The distance within which the band's nodes find their closest point: a node of a touched cell is
// within a cell diagonal of the surface; each extra layer adds a cell.
inline double bandSearchRadius(const GridLattice& lattice, int extraLayers)
{
  return 1.001 * (1 + extraLayers) * lattice.spacing.norm();
}
// Band nodes this close to the surface have no side.
inline double onSurfaceDistance(const GridLattice& lattice)
{
  return 1e-6 * lattice.minSpacing();
}
// imin, imax, jmin, jmax, kmin, kmax of the given nodes (imin > imax when there are none).
std::array<int, 6> nodeExtent(const GridLattice& lattice, const IndexList& nodes);

inline std::array<bool, 6> allFaces(bool on)
{
  return { on, on, on, on, on, on };
}
IndexList bandNodes(const GridLattice& lattice, const IndexList& cells, int extraLayers,
  const std::array<bool, 6>& gridFaces, std::uint8_t* state);

// Exact distances, closest points and signs at the band nodes; the signs go into state too (band
// nodes within `onSurface` of the surface stay BandOnSurface). Returns false if aborted.
// searchRadius bounds the distance of band nodes near the surface (a node farther off is searched
// again without bound).
bool computeBand(const DistanceSource& source, const GridLattice& lattice, IndexList nodes,
  double searchRadius, double onSurface, const Progress& progress, DistanceBand& band,
  std::uint8_t* state);

} // namespace shrinkwrap

#endif
