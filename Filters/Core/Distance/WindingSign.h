// Sign of Algorithm 1, line 8, where the votes disagree (SignVotes.h): a hole lets one region reach
// both sides of the surface, or parts of it cross or overlap. Each node then takes the side of its
// closest surface point (its site from the closest-point passes) by that point's pseudonormal where
// the side is sure: the pseudonormal is defined (not on a rim or a non-manifold edge) and the
// generalized winding number confirms the triangle's two sides (not inside another part, not
// crossing one, ConfirmedSides.h). Elsewhere the winding number itself decides: inside where |w| >
// 1/2 (Jacobson et al. 2013), which closes small holes and takes the union of overlapping parts.
#ifndef ShrinkWrap_WindingSign_h
#define ShrinkWrap_WindingSign_h

#include "Distance/DistanceBand.h"
#include "Distance/DistanceSource.h"

#include <cstdint>

namespace shrinkwrap
{

struct WindingSignResult
{
  bool completed = false;    // false: progress asked to stop
  long long evaluated = 0;   // nodes whose side the winding number gave
  long long inside = 0;      // nodes found inside (0: the surface encloses nothing)
  long long unconfirmed = 0; // triangles whose sides the winding number does not confirm
};

// Per band node, the normal its side may be taken from: its pseudonormal where that is sure and
// the triangle's sides are confirmed, else zero (the winding number decides).
SiteList trustedNormals(const DistanceSource& source, const DistanceBand& band);

// Relabels every node of `state` (BandOnSurface nodes stay). `site`: each node's site from the
// closest-point passes, an index into sitePoints and siteNormals (trustedNormals of the band, and
// of other processes' sites for a slab). The source must have a winding number (sidesConfirmed()
// not empty).
WindingSignResult signByWindingNumber(const DistanceSource& source, const GridLattice& lattice,
  const SiteList& sitePoints, const SiteList& siteNormals, const std::int32_t* site,
  std::uint8_t* state, const Progress& progress);

} // namespace shrinkwrap

#endif
