// Algorithm 1 of the paper: the signed distance of a triangle soup at the nodes of a lattice.
#ifndef ShrinkWrap_SignedDistance_h
#define ShrinkWrap_SignedDistance_h

#include "DistanceGrid.h"
#include "DistanceSource.h"
#include "GridLattice.h"
#include "Progress.h"
#include "Status.h"
#include "TriangleSoup.h"

#include <cstdint>
#include <memory>
#include <string>

namespace shrinkwrap
{

enum class SweepMethod
{
  ClosestPoint, // propagate closest surface points (default: more exact at the same speed)
  Eikonal       // the paper's fast sweeping of |grad d| = 1 [16]
};

struct SignedDistanceSettings
{
  SweepMethod sweep = SweepMethod::ClosestPoint;
  int bandLayers = 1;   // node layers of exact distances beyond the nodes of the cells the surface touches
  int eikonalIterations = 1; // repetitions of the eight Eikonal sweeps
  bool computeSign = true;
};

struct SignedDistanceResult
{
  bool completed = false; // false: aborted, the values are incomplete
  bool isSigned = false;  // false: unsigned, because the outside leaked in or sign was not asked for
  bool invertedOrientation = false; // the triangles face inwards; signs follow the geometry
  long long bandNodes = 0;
  long long boundaryEdges = 0;
  long long nonManifoldEdges = 0;
  long long signDisagreements = 0;
  // Seconds per stage.
  double treeSeconds = 0, outlineSeconds = 0, bandSeconds = 0, sweepSeconds = 0, signSeconds = 0;
};

// Bytes per grid node the computation needs besides the output values and the mesh.
int workingBytesPerNode(const SignedDistanceSettings& settings);

// Fills `distance` (lattice.nodeCount() values, x fastest) with the signed distance to the soup:
// negative inside, positive outside. The soup must be non-empty with finite coordinates.
SignedDistanceResult computeSignedDistance(const TriangleSoup& soup, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress = {});
// The same for any distance source (DistanceSource.h); the soup's form builds a TriangleSource, and
// a TriangleSource's form also counts its boundary and non-manifold edges.
SignedDistanceResult computeSignedDistance(const DistanceSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress = {});
SignedDistanceResult computeSignedDistance(const TriangleSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress = {});

// Why a soup has no distance field, if it has none: no triangles, NaN or infinite coordinates,
// coordinates beyond kLargestCoordinate, or only degenerate triangles.
Status checkSoup(const TriangleSoup& soup);

// Refuses a grid that cannot fit in the memory the machine has now (with the working memory of
// `settings`), before anything is allocated for it.
Status checkMemory(const GridLattice& lattice, const SignedDistanceSettings& settings);

// The whole of Mesh Signed Distance for a caller that wants the field itself (Shrink Wrap, without a
// DistanceField input): checks, the lattice placed around the soup's bounds, and the distances. An
// aborted run leaves `grid` empty and the result's `completed` false. `target`, if given, receives
// the soup's TriangleSource (its AABB tree answers exact closest-point queries later).
Status signedDistanceGrid(const TriangleSoup& soup, const Box& bounds, const GridPlacement& placement,
  const SignedDistanceSettings& settings, DistanceGrid& grid, SignedDistanceResult& result,
  const Progress& progress = {}, std::shared_ptr<const TriangleSource>* target = nullptr);

} // namespace shrinkwrap

#endif
