// Algorithm 1 of the paper: the signed distance of a triangle soup at the nodes of a lattice.
#ifndef ShrinkWrap_SignedDistance_h
#define ShrinkWrap_SignedDistance_h

#include "Common/Notes.h"
#include "Common/Progress.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/DistanceGrid.h"
#include "Distance/DistanceSource.h"
#include "Distance/GridLattice.h"
#include "Distance/PointSource.h"

#include <cstdint>
#include <memory>
#include <optional>
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
  int bandLayers =
    1; // node layers of exact distances beyond the nodes of the cells the surface touches
  int eikonalIterations = 1; // repetitions of the eight Eikonal sweeps
  bool computeSign = true;
  // Where the sign votes disagree (holes, crossings, overlaps): the generalized winding number
  // decides (WindingSign.h); false: such a field stays unsigned, as the paper's Algorithm 1 leaves
  // it.
  bool windingNumber = true;
};

enum class SignMethod
{
  None,           // unsigned: not asked for, or the surface encloses nothing
  Votes,          // every region's votes agreed (a closed surface that does not cross itself)
  WindingNumber,  // the votes disagreed: sides in doubt by the generalized winding number
                  // (WindingSign.h)
  VotesDisagreed  // unsigned: the votes disagreed (open or crossing) and no winding number was
                  // asked for (SignedDistanceSettings::windingNumber false)
};

struct SignedDistanceResult
{
  bool completed = false; // false: aborted, the values are incomplete
  bool isSigned =
    false; // false: unsigned, because sign was not asked for or the surface encloses nothing
  SignMethod signMethod = SignMethod::None;
  bool invertedOrientation = false; // the triangles face inwards; signs follow the geometry
  long long bandNodes = 0;
  long long boundaryEdges = 0;
  long long nonManifoldEdges = 0;
  long long signDisagreements = 0;
  long long reorientedTriangles = 0;  // turned to agree with their neighbours (TriangleSource)
  long long unconfirmedTriangles = 0; // inside another part or crossing one (by the winding number)
  long long windingEvaluations = 0;   // nodes whose side the winding number gave
  long long points = 0;               // > 0: measured from this many input points (unsigned)
  long long triangles = 0; // with points: and from this many triangles (a union, unsigned)
  // Seconds per stage.
  double treeSeconds = 0, outlineSeconds = 0, bandSeconds = 0, sweepSeconds = 0, signSeconds = 0;
};

// What a field's sign rests on, in words for a user: closed or not, crossing itself or not, how the
// sign was decided (or why there is none). `asked`: whether a sign was asked for.
std::string signStatus(const SignedDistanceResult& result, bool asked);
// How a user should hear of signStatus: a warning when there is no sign although one was asked for
// (and there were polygons to sign), a fact when the winding number or the geometry decided it
// (an open or crossing surface, triangles facing inwards); nothing for a closed surface's sign.
std::optional<Note::Kind> signNoteKind(const SignedDistanceResult& result, bool asked);

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
// The unsigned distance to the nearest of `points` (a scan, sampled points): a PointSource
// through the same band and sweeps; `settings.computeSign` does not apply (points have no inside).
SignedDistanceResult computePointDistance(const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress = {});
SignedDistanceResult computePointDistance(const PointSource& source, const GridLattice& lattice,
  const SignedDistanceSettings& settings, float* distance, const Progress& progress = {});
// The unsigned distance to the nearest of the soup's triangles and the points (a mesh with loose
// points, a scan beside a model; UnionSource.h).
SignedDistanceResult computeUnionDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress = {});

// The field of `soup` and `points` together, by which of them there are: the soup's signed field,
// the points' unsigned one, or the unsigned distance to the nearer of both.
SignedDistanceResult computeDistance(const TriangleSoup& soup, const std::vector<Vec3>& points,
  const GridLattice& lattice, const SignedDistanceSettings& settings, float* distance,
  const Progress& progress = {});

// Why points have no distance field, if they have none: none at all, or NaN, infinite or
// out-of-range coordinates.
Status checkPoints(const std::vector<Vec3>& points);
Status checkPoints(const PointList& points);

// Why a soup has no distance field, if it has none: no triangles, NaN or infinite coordinates,
// coordinates beyond kLargestCoordinate, or only degenerate triangles.
Status checkSoup(const TriangleSoup& soup);

// Refuses a grid that cannot fit in the memory the machine has now (with the working memory of
// `settings`), before anything is allocated for it.
Status checkMemory(const GridLattice& lattice, const SignedDistanceSettings& settings);

// The whole of Mesh Signed Distance for a caller that wants the field itself (Shrink Wrap, without
// a DistanceField input): checks (the soup, the memory), and the distances on `lattice`. An aborted
// run leaves `grid` empty and the result's `completed` false. `target`, if given, receives the
// soup's TriangleSource (its AABB tree answers exact closest-point queries later).
Status signedDistanceGrid(const TriangleSoup& soup, const GridLattice& lattice,
  const SignedDistanceSettings& settings, DistanceGrid& grid, SignedDistanceResult& result,
  const Progress& progress = {}, std::shared_ptr<const TriangleSource>* target = nullptr);

} // namespace shrinkwrap

#endif
