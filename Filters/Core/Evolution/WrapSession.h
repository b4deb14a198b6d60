// One shrink-wrap run (Algorithm 3) as a session the filter keeps while its inputs and properties
// stay: the target's distance field, the evolver, and the cache of computed steps. Asking for a step
// computes what is missing from the nearest cached step before it.
#ifndef ShrinkWrap_WrapSession_h
#define ShrinkWrap_WrapSession_h

#include "Evolution/Evolver.h"
#include "Distance/PointSource.h"
#include "Distance/PointSurface.h"
#include "Evolution/StartingSurface.h"
#include "Evolution/StepCache.h"

#include <array>
#include <memory>
#include <string>

namespace shrinkwrap
{

// Every setting of a wrap, with Shrink Wrap's defaults: the one place they are stated (the filter's
// properties start from them).
struct WrapSettings
{
  EvolverSettings evolution;
  StartSettings start;
  int steps = 25;               // N_t (the paper's Fig. 11: 200, from an icosphere at C = 1)
  bool automaticScaling = true; // phi of Section 2.4
  // Cells along the longest axis of the distance field computed here. 80 (over the offset start's box,
  // about 1.25 times the target) rather than 120: the exact near field lands the wrap, the grid serves
  // the far field, the start and the gap closing, and its cost is most of a wrap's fixed time.
  int resolution = 80;
  double cacheMiB = 512;        // memory for cached steps
  // Remeshing after every step towards the target edge length L (EvolverSettings::remeshing), so the
  // vertex count follows the surface; phi then follows L (StabilityScaling.h).
  bool remeshing = true;
  double targetLength = 0;      // L, in the target's units; 0: automatic (kAutomaticDivisor)
  // Adaptive edge length: edges between edgeRange[0] L and edgeRange[1] L, shorter where the surface
  // curves (RemeshSettings::shortest, longest); {1, 1}: L everywhere.
  std::array<double, 2> edgeRange{ 1, 1 };
  double gapSize = 0;           // gaps narrower than this are bridged (GapClosing.h); 0: automatic
  // An open or self-crossing target's field (computed here): false, unsigned, so that holes wider than
  // the gap size stay open and the wrap enters them, wrapping open sheets from both sides (measured
  // best on CGAL's open CAD part and the dragon, RESULTS.md); true, signed by the generalized winding
  // number (WindingSign.h), which closes every hole (best for scans with missing patches, e.g. the
  // open elephant).
  bool closeHoles = false;
  bool exactNearTarget = true;  // d and grad d from the target's closest point near it (TargetDistance.h)
  double exactBand = 2;         // in cells of the field

  // The automatic sizes: the target's bounding-box diagonal over these.
  static constexpr double kLengthDivisor = 50;
  static constexpr double kGapDivisor = 50;
  static constexpr double kMaxVertices = 4e6; // a Target Edge Length that would make more is refused
  // The adaptive chord error, in L: with edges between 0.6 L and 1.6 L the wraps of the benchmark's
  // meshes keep about as many vertices as with L alone (RESULTS.md).
  static constexpr double kChordError = 0.12;
  static constexpr double kShortestEdge = 0.1, kLongestEdge = 4; // the bounds of edgeRange

  Status validate() const;
  // These settings with the automatic sizes resolved for a target of this box, and L passed on to
  // the evolution.
  WrapSettings resolved(const Box& targetBox) const;
  // Resolved settings: whether the Target Edge Length is sane for a target of this box.
  Status fits(const Box& targetBox) const;
  // The placement of the field computed here: at the Resolution, in a box just large enough for the
  // offset start and the gap closing (cells spent on the object), or the paper's for the icosphere or
  // a given start, which may lie anywhere around the target. Resolved settings.
  GridPlacement fieldPlacement(const Box& targetBox, bool givenStart) const;
};

// The distances a wrap moves on.
struct WrapFields
{
  TargetDistance driving; // to the target closed over gaps narrower than the gap size
  TargetDistance target;  // to the target itself: what the output's closeness measures
};

// The fields of a wrap from the target's grid (signed or not) and, when `exact` is given, the target
// itself for the near field; `settings` resolved.
Status wrapFields(DistanceGrid grid, bool isSigned, std::shared_ptr<const DistanceSource> exact,
  const WrapSettings& settings, WrapFields& fields);
// Why points cannot be wrapped, if they cannot: they coincide, or lie on a line or in a plane (within
// 1e-6 of their extent), so they enclose nothing. (checkPoints first: finite, not empty.)
Status checkPointsEnclose(const PointList& points);
// A point cloud as a wrap takes it, measured once: the nearest point, the median neighbour distance
// and that of the cloud's sparsest part (PointSpacing), and the surface the points sample
// (PointSurface, fitted at a few spacings; none where the spacing is 0), which also measures their
// noise.
struct PointCloud
{
  std::shared_ptr<const PointSource> points;
  std::shared_ptr<const PointSurface> surface;
  double spacing = 0;
  double sparseSpacing = 0; // at least `spacing` where measured; 0 (none) counts as `spacing`
  double noise() const; // PointSurface::typicalNoise, 0 without a surface
};
PointCloud measureCloud(PointList points);
// Settings for a wrap onto `cloud` within `box`: the automatic sizes (0) from its spacing: the Target
// Edge Length (coarser on a noisy cloud), and the Gap Size, at least a few cells of the field computed
// for them (placed with `givenStart`) so that the grid resolves the closing; with the automatic gap, a
// finer field (Resolution up to 1.5 times) for a dense cloud, so that those cells do not widen the gap
// far beyond the spacing's, and for a clean one whose gap spans few cells, so that they resolve it.
WrapSettings withPointSizes(WrapSettings settings, const Box& box, const PointCloud& cloud, bool givenStart);
// The fields of a wrap onto points (issue #13) from their unsigned grid: the wrap is driven by the
// distance to the points closed by a ball of half the gap size (the union of balls around them,
// eroded: a surface through the outer points that spans the gaps between them), and its closeness
// is measured to the points themselves. `polygons`, if given, are wrapped with the points (Input
// Geometry "Polygons and Points"): `grid` is then the distance to both, and near them the wrap lands
// on the nearer of the polygons and the points' fitted surface.
Status pointWrapFields(DistanceGrid grid, const PointCloud& cloud, const WrapSettings& settings, WrapFields& fields,
  std::shared_ptr<const DistanceSource> polygons = nullptr);

class WrapSession
{
public:
  // `start` ready to evolve (startingSurface()); `settings` resolved. `targetBox` centres the scaled
  // coordinates and, without remeshing, sizes phi (Section 2.4: the mean co-volume of the sphere
  // inscribed in the target's box is tau).
  static Status create(WrapFields fields, const Box& targetBox, const SurfaceMesh& start,
    const WrapSettings& settings, std::unique_ptr<WrapSession>& session);

  // The step shown for a wanted one: after a failure, the last good step at most.
  int shown(int wanted) const { return this->LastGood >= 0 ? std::min(wanted, this->LastGood) : wanted; }
  // Computes the missing steps up to shown(k); false when progress asked to stop (the steps computed
  // stay cached).
  bool advanceTo(int k, const Progress& progress = {});
  // The surface of step k (or the nearest cached one before it) in the caller's units.
  struct Surface
  {
    int step = 0;
    std::vector<Vec3> points;
    const StepCache::Step* cached = nullptr;
  };
  Surface surface(int k) const;

  // Edits the evolver's current surface (Evolver::edit); phi follows the new vertex count when the
  // settings scale automatically, the current step is cached anew and later ones are dropped.
  Status edit(const std::function<void(SurfaceMesh&)>& change);

  const WrapFields& fields() const { return this->Fields; }
  const WrapSettings& settings() const { return this->Settings; }
  const Evolver& evolver() const { return *this->Evolution; }
  int computedSteps() const { return this->Computed; }
  int lastGood() const { return this->LastGood; }
  const std::string& failure() const { return this->Failure; }

private:
  WrapSession() = default;
  double scaleFor(int vertexCount) const;
  void cacheCurrent(bool connectivityChanged, bool edited = false);

  WrapSettings Settings;
  WrapFields Fields;
  double Radius = 1; // of the sphere inscribed in the target's box
  std::unique_ptr<Evolver> Evolution;
  StepCache Cache;
  StepCache::Triangles EvolverTriangles; // the evolver's current connectivity
  int LastGood = -1; // set when a step failed: the last step that did not
  std::string Failure;
  int Computed = 0;
};

} // namespace shrinkwrap

#endif
