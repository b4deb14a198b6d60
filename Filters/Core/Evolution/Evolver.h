// Lagrangian evolution of a closed triangle surface by eq. (2) of the paper:
//   dF/dt = eps(d) Laplace-Beltrami(F) + eta(d) N + v_T,
// with eps(d) = C1 (1 - exp(-d^2/C2)) (eq. (3)) and eta(d) = C d ((-grad d . N) - D sqrt(1 - (grad
// d . N)^2)) (eq. (4)), d the signed distance to the target. One step is semi-implicit finite
// volumes with barycentric co-volumes and cotangent weights (Section 2.2); per vertex i and
// coordinate:
//   (1 + tau eps_i/|V_i| sum_j w_ij) F_i - tau eps_i/|V_i| sum_j w_ij F_j = F_i^old + tau eta_i N_i
//   + tau v_T,i.
// A step may end with remeshing towards a target edge length (Remesher.h: splits, collapses,
// valence flips, relaxation), so the vertex count follows the surface as it moves into concavities
// and along thin parts; with edge flips (EdgeFlips.h), which change the triangles and not the
// vertices; and with edge collapses (EdgeCollapses.h), which merge the ends of the short edges of
// degenerating triangles. Callers may edit the surface between steps (edit()), e.g. split edges.
// Positions may be scaled for stability (Section 2.4, StabilityScaling.h): the evolver works in
// scaled coordinates and callers only ever see their own units.
#ifndef ShrinkWrap_Evolver_h
#define ShrinkWrap_Evolver_h

#include "Common/Progress.h"
#include "Common/Status.h"
#include "Distance/TargetDistance.h"
#include "Evolution/RimCoverage.h"
#include "Remeshing/EdgeCollapses.h"
#include "Remeshing/EdgeFlips.h"
#include "Remeshing/Remesher.h"
#include "Surface/SurfaceGeometry.h"

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shrinkwrap
{

enum class Redistribution
{
  None,
  Angle, // Section 2.3, Medl'a et al. [5]
  Volume // asymptotically uniform, Mikula et al. [11]
};

enum class LinearSolver
{
  ConjugateGradient, // the symmetric form: rows scaled by |V_i|/eps_i (default: fastest, same
                     // results)
  BiCGSTAB           // the paper's: the rows as printed, BiCGSTAB with a diagonal preconditioner
};

// The defaults are Shrink Wrap's (what serves real meshes best; the filter shows them); paper()
// gives the scheme exactly as the paper runs it, for the tests that reproduce its tables.
struct EvolverSettings
{
  double timeStep = 0.015; // tau (paper Fig. 11)
  double C1 = 1.0; // eq. (3); C2 = 0 makes eps = C1 everywhere (pure MCF: C1 = 1, C2 = 0, C = 0)
  double C2 = 1.0;
  // Eq. (4). C = 12 (the paper's 1) lands the offset start on the target in 25 steps: advection
  // closes a share tau C (0.18) of the remaining distance per step (0.82^25 < 1%). D = 0.5 (the
  // paper's 0) pushes the membranes D = 0 spans over concave parts inwards.
  double C = 12.0;
  double D = 0.5;
  // Where the vertices land: d = facetFit h / 4 instead of d = 0 (eq. (4) moves them by d minus
  // that), h a vertex's height over its ring's centroid along its normal (positive where the
  // surface is convex; within half the ring's mean edge l, so h / 4 <= l / 8). On a sphere of
  // radius R with edges l, h = l^2 / (2R) and h / 4 = l^2 / (8R) is an edge's sagitta: facets
  // between vertices on the target cut inside convex parts by about that (and bulge out of concave
  // ones), so vertices that far out make the facets straddle the target instead. With remeshing
  // only (its rings are near equilateral), and not at the vertices that hold rims. Stable: a vertex
  // pushed out by e raises its own landing by e / 4. 0: on the target (the paper's scheme).
  double facetFit = 1.0;
  Redistribution redistribution =
    Redistribution::Angle;  // the paper's tables also run None and Volume
  double omegaAngle = 0.5;  // omega_angle (paper Fig. 11)
  double omegaVolume = 1.0; // omega_vol (paper Table 3)
  // Off, unlike the paper: rho vanishes on the target, where angles matter most, and with edge
  // flips the full angle weight is stable.
  bool distanceWeight = false; // weight omega_angle by rho(d) = A (1 - exp(-d^2)), eq. (10)
  double rhoA = 1.0;           // A
  // Connectivity adjustments, which the paper's Section 5 names as the missing piece.
  bool edgeFlips = true; // flip edges after each step (EdgeFlips.h)
  FlipSettings flips;
  bool edgeCollapses = true; // collapse the short edges of degenerating triangles (EdgeCollapses.h)
  CollapseSettings collapses;
  // Remeshing after every step towards remeshing->targetLength (in the caller's units); none when
  // unset. One iteration per step: the surface moves little in a step, so the steps converge it.
  std::optional<RemeshSettings> remeshing;
  // Vertices hold back where their step would break the surface: fronts stop where they meet
  // (SelfIntersections.h: holdNewCrossings), so the surface never passes through itself where two
  // of its parts come together, and a vertex whose step would degenerate a triangle stays where it
  // was.
  bool holdBack = true;
  // After every step with remeshing, the target's rims outside the surface pull it onto them
  // (RimCoverage.h; needs the field's exact near target).
  RimSettings rims;
  bool volumePerArea =
    true; // v_T = (integral of grad psi over V_i) / |V_i|; false: the paper's code
  LinearSolver solver = LinearSolver::ConjugateGradient;
  double solverTolerance = 1e-6; // relative residual: positions to about 1e-6 of the scaled size
  double minAngle = 1e-3;        // radians: a smaller triangle angle is a failure (scale free)

  // The paper's scheme: C = 1, D = 0, no redistribution (its tables set it), rho(d) on, no
  // connectivity changes, solves to 1e-10.
  static EvolverSettings paper()
  {
    EvolverSettings s;
    s.redistribution = Redistribution::None;
    s.distanceWeight = true;
    s.edgeFlips = false;
    s.edgeCollapses = false;
    s.C = 1.0;
    s.D = 0.0;
    s.facetFit = 0.0;
    s.remeshing.reset();
    s.holdBack = false;
    s.rims.cover = false;
    s.solverTolerance = 1e-10;
    return s;
  }
  static RemeshSettings duringEvolution()
  {
    RemeshSettings r;
    r.iterations = 1;
    // No relaxation: the angle redistribution already moves vertices tangentially, and relaxing
    // where two parts of the surface nearly touch lets them cross.
    r.relaxWeight = 0;
    return r;
  }
};

enum class Failure
{
  None,
  NotANumber,
  DegenerateTriangle,
  LeftDomain,
  SolverFailed,
  EditFailed,
  Stopped // the step was stopped (Evolver::setStop); the surface is no step's: restart it
};

struct StepReport
{
  Failure failure = Failure::None;
  int step = 0;   // the step that failed, counted from 1
  int where = -1; // the vertex or triangle concerned
  std::string message;
  int flips = 0;     // edges flipped after the step
  int collapses = 0; // edges collapsed after the step (vertices removed)
  int splits = 0;    // edges split after the step (vertices added)
  int held = 0;      // vertices held back where fronts met
  int vanished = 0;  // parts of the surface that shrank to a few vertices and were removed
  int rimMoves = 0;  // vertices moved onto the target's rims after the step
  double smallestAngle =
    M_PI; // radians, over the triangles at the end of the step (before any repair)
  bool ok() const { return this->failure == Failure::None; }
  bool connectivityChanged() const
  {
    return this->flips > 0 || this->collapses > 0 || this->splits > 0 || this->vanished > 0;
  }
};

class Evolver
{
public:
  // `field` may be null (then d = 0, grad d = 0: eps = C1 when C2 = 0, eta = 0). `domain` bounds
  // the vertices (in the caller's units); `scale` (phi) and `center` define the scaled coordinates
  // y = phi (x - center). Check `status()` after construction.
  Evolver(const SurfaceMesh& mesh, const EvolverSettings& settings,
    const TargetDistance* field = nullptr, const Box& domain = Box(), double scale = 1.0,
    const Vec3& center = Vec3::Zero());
  ~Evolver();

  const Status& status() const { return this->Valid; }

  // One time step; after a failure the surface stays that of the last good step. `stop`, if set,
  // is asked between the step's phases and its remeshing's passes: true stops the step there
  // (Failure::Stopped), and the surface must be restarted from a cached step.
  StepReport step();
  void setStop(std::function<bool()> stop) { this->Stop = std::move(stop); }
  // Up to n steps, reporting progress after each; stops at a failure (returned) or when progress
  // asks to stop.
  StepReport run(int n, const Progress& progress = {});
  int steps() const { return this->Steps; }
  double time() const
  {
    return this->Steps * this->Settings.timeStep / (this->Scale * this->Scale);
  }

  // Current positions in the caller's units.
  std::vector<Vec3> positions() const { return this->positionsOf(this->Mesh.points()); }
  // The exact state (scaled coordinates): what a cache keeps to restart from bit for bit, and the
  // caller's positions for a state.
  const std::vector<Vec3>& state() const { return this->Mesh.points(); }
  std::vector<Vec3> positionsOf(const std::vector<Vec3>& state) const;
  // Continues from an earlier state as the result of step `steps`, e.g. a cached step, with its
  // triangles when they differ from the current ones (always when the vertex count differs); false
  // if they do not form a closed 2-manifold, and then nothing changes. A state of another scale
  // (after setScale) comes with it.
  bool restart(const std::vector<Vec3>& state, const std::vector<std::array<int, 3>>* triangles,
    int steps, double scale = 0);
  // Local edits of the surface between steps (SurfaceMesh's split, flip, collapse; positions are
  // the scaled state, so edits should interpolate, as split does): committed, then the solver
  // follows.
  Status edit(const std::function<void(SurfaceMesh&)>& change);
  // phi of Section 2.4, e.g. recomputed for a new vertex count (StabilityScaling.h); the surface
  // stays where it is in the caller's units.
  double scale() const { return this->Scale; }
  const Vec3& center() const { return this->Center; }
  void setScale(double scale);
  // Geometry of the current positions, in the caller's units (areas, weights and curvatures
  // rescaled).
  SurfaceGeometry geometry() const;
  // The tangential velocity used in the last step, in the caller's units per unit time.
  std::vector<Vec3> tangentialVelocity() const;
  const SurfaceMesh& mesh() const { return this->Mesh; }

private:
  bool stopped() const { return this->Stop && this->Stop(); }
  StepReport fullStep(); // step() but for what a stopped step restores
  struct Controls;
  struct Solver;
  Controls controls() const; // incomplete when stopped()
  // Vertex i's height over the centroid of its ring along `normal`, within half the ring's mean
  // edge (EvolverSettings::facetFit).
  double heightOverRing(int i, const Vec3& normal) const;
  bool tangentialVelocities(const Controls& c, std::vector<Vec3>& vt);
  bool solve(const Controls& c, const std::vector<Vec3>& vt, std::vector<Vec3>& next);
  StepReport accept(std::vector<Vec3>& next, std::vector<Vec3>& vt, bool converged);
  StepReport check(const std::vector<Vec3>& y) const;
  // Appends to HeldNear where it held vertices against a crossing.
  int holdBack(std::vector<Vec3>& next);
  int coverRims(); // RimCoverage.h: the vertices moved
  std::vector<Vec3> scaledRimSamples() const;
  void adjustConnectivity(
    StepReport& report); // remeshing, flips, then collapses, as the settings ask
  // A new solver for the new triangles; the volume redistribution's warm start only for the same
  // vertices.
  void connectivityChanged(bool sameVertices);
  // Removes the parts of the surface with at most kVanishedVertices vertices that hold a triangle
  // under the smallest angle: a part of the wrap smaller than the edge length (about a target part
  // that small) shrinks to a tetrahedron and would fold. Returns how many.
  int removeVanishedParts();
  std::vector<Vec3>& velocity()
  {
    return this->Mesh.addVertexProperty<Vec3>(kVelocity, Vec3::Zero()).values();
  }
  static constexpr const char* kVelocity = "v:velocity"; // Vec3: v_T of the last step

  SurfaceMesh Mesh; // positions: the scaled state; and the property kVelocity
  EvolverSettings Settings;
  const TargetDistance* Field;
  Box Domain; // scaled
  double Scale;
  Vec3 Center;
  Status Valid;
  std::vector<Vec3> RimSamples; // the target's rims, in the caller's units (RimCoverage.h)
  // Where the edits of the last kRememberedSteps steps crossed (CheckedEdits.h): guarded from the
  // start.
  static constexpr std::size_t kRememberedSteps = 3;
  std::deque<std::vector<Box>> RecentCrossings;
  // Where the hold-back kept two parts of the surface from crossing since the last edits: they
  // nearly touch there, and while crossings are recent the next edits are guarded there from the
  // first try.
  std::vector<Box> HeldNear;
  int Steps = 0;
  std::function<bool()> Stop;    // asked between phases (setStop)
  std::vector<double> Potential; // the volume redistribution's warm start
  std::unique_ptr<Solver> Linear;
};

// Positions in the caller's units of a state in the scaled coordinates y = scale (x - center).
std::vector<Vec3> unscaled(const std::vector<Vec3>& state, double scale, const Vec3& center);

} // namespace shrinkwrap

#endif
