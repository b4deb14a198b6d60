// Edge splits: the edit that adds vertices where the surface stretches (adaptive remeshing,
// will choose the edges by length against a target; for now the caller names them).
#ifndef ShrinkWrap_EdgeSplits_h
#define ShrinkWrap_EdgeSplits_h

#include "Common/Progress.h"
#include "Surface/SurfaceMesh.h"

#include <array>
#include <vector>

namespace shrinkwrap
{

// Every edge (i, j) of the mesh once, i < j, in ring order.
std::vector<std::array<int, 2>> edgesOf(const SurfaceMesh& mesh);

// Splits each edge at its midpoint (vertex data interpolated; SurfaceMesh::split), committed. The
// edges are those of the mesh before the call, so an edge split earlier in the list may have made a
// later one's triangles new: each split finds its edge's current triangles. Returns the splits
// made. `stop` (StopPoll) ends the splits early; those made are committed.
int splitEdges(SurfaceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
  const std::function<bool()>& stop = {});

} // namespace shrinkwrap

#endif
