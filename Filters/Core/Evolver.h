// Lagrangian evolution of a closed triangle surface by eq. (2) of the paper:
//   dF/dt = eps(d) Laplace-Beltrami(F) + eta(d) N + v_T,
// with eps(d) = C1 (1 - exp(-d^2/C2)) (eq. (3)) and eta(d) = C d ((-grad d . N) - D sqrt(1 - (grad d . N)^2))
// (eq. (4)), d the signed distance to the target. One step is semi-implicit finite volumes with
// barycentric co-volumes and cotangent weights (Section 2.2); per vertex i and coordinate:
//   (1 + tau eps_i/|V_i| sum_j w_ij) F_i - tau eps_i/|V_i| sum_j w_ij F_j = F_i^old + tau eta_i N_i + tau v_T,i.
// A step may end with edge flips (EdgeFlips.h), which change the triangles and not the vertices, and
// edge collapses (EdgeCollapses.h), which merge the ends of the short edges of degenerating triangles.
// Positions may be scaled for stability (Section 2.4, StabilityScaling.h): the evolver works in scaled
// coordinates and callers only ever see their own units.
#ifndef ShrinkWrap_Evolver_h
#define ShrinkWrap_Evolver_h

#include "DistanceGrid.h"
#include "EdgeCollapses.h"
#include "EdgeFlips.h"
#include "SurfaceGeometry.h"

#include <memory>
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
  ConjugateGradient, // the symmetric form: rows scaled by |V_i|/eps_i (default: fastest, same results)
  BiCGSTAB           // the paper's: the rows as printed, BiCGSTAB with a diagonal preconditioner
};

struct EvolverSettings
{
  double timeStep = 0.015; // tau (paper Fig. 11)
  double C1 = 1.0;         // eq. (3); C2 = 0 makes eps = C1 everywhere (pure MCF: C1 = 1, C2 = 0, C = 0)
  double C2 = 1.0;
  double C = 1.0;          // eq. (4)
  double D = 0.0;
  Redistribution redistribution = Redistribution::None;
  double omegaAngle = 0.5;      // omega_angle (paper Fig. 11)
  double omegaVolume = 1.0;     // omega_vol (paper Table 3)
  // The paper's scheme by default; the filter turns on edge flips and turns off rho, which vanishes on
  // the target: with flips the full angle weight is stable and keeps angles good where it matters.
  bool distanceWeight = true;   // weight omega_angle by rho(d) = A (1 - exp(-d^2)), eq. (10)
  double rhoA = 1.0;            // A
  bool edgeFlips = false;       // flip edges after each step (EdgeFlips.h)
  FlipSettings flips;
  bool edgeCollapses = false;   // collapse the short edges of degenerating triangles (EdgeCollapses.h)
  CollapseSettings collapses;
  bool volumePerArea = true;    // v_T = (integral of grad psi over V_i) / |V_i|; false: the paper's code
  LinearSolver solver = LinearSolver::ConjugateGradient;
  double solverTolerance = 1e-10; // relative residual
  double minAngle = 1e-3;         // radians: a smaller triangle angle is a failure (scale free)
};

enum class Failure
{
  None,
  NotANumber,
  DegenerateTriangle,
  LeftDomain,
  SolverFailed
};

struct StepReport
{
  Failure failure = Failure::None;
  int step = 0;      // the step that failed, counted from 1
  int where = -1;    // the vertex or triangle concerned
  std::string message;
  int flips = 0;     // edges flipped after the step
  int collapses = 0; // edges collapsed after the step (vertices removed)
  double smallestAngle = M_PI; // radians, over the triangles at the end of the step (before any repair)
  bool ok() const { return this->failure == Failure::None; }
};

class Evolver
{
public:
  // `field` may be null (then d = 0, grad d = 0: eps = C1 when C2 = 0, eta = 0). `domain` bounds the
  // vertices (in the caller's units); `scale` (phi) and `center` define the scaled coordinates
  // y = phi (x - center). Check `error()` after construction.
  Evolver(const SurfaceMesh& mesh, const EvolverSettings& settings, const DistanceGrid* field = nullptr,
    const Box& domain = Box(), double scale = 1.0, const Vec3& center = Vec3::Zero());
  ~Evolver();

  const std::string& error() const { return this->Error; }

  // One time step; after a failure the positions stay those of the last good step.
  StepReport step();
  int steps() const { return this->Steps; }
  double time() const { return this->Steps * this->Settings.timeStep / (this->Scale * this->Scale); }

  // Current positions in the caller's units.
  std::vector<Vec3> positions() const { return this->positionsOf(this->Y); }
  // The exact state (scaled coordinates): what a cache keeps to restart from bit for bit, and the
  // caller's positions for a state.
  const std::vector<Vec3>& state() const { return this->Y; }
  std::vector<Vec3> positionsOf(const std::vector<Vec3>& state) const;
  // Continues from an earlier state as the result of step `steps`, e.g. a cached step, with its
  // triangles when they differ from the current ones (always when the vertex count differs); false if
  // they do not form a closed 2-manifold, and then nothing changes.
  bool restart(const std::vector<Vec3>& state, const std::vector<std::array<int, 3>>* triangles, int steps);
  // Takes new triangles on the same vertices (e.g. a cached step's after edge flips); false if they
  // are not a closed 2-manifold, and then nothing changes.
  bool reconnect(const std::vector<std::array<int, 3>>& triangles);
  // Geometry of the current positions, in the caller's units (areas, weights and curvatures rescaled).
  SurfaceGeometry geometry() const;
  // The tangential velocity used in the last step, in the caller's units per unit time.
  std::vector<Vec3> tangentialVelocity() const;
  const SurfaceMesh& mesh() const { return this->Mesh; }

private:
  struct Solver;
  void sampleField(std::vector<double>& d, std::vector<Vec3>& grad) const;
  StepReport check(const std::vector<Vec3>& y) const;
  bool reset(const std::vector<Vec3>& y, const std::vector<std::array<int, 3>>& triangles);
  void adjustConnectivity(StepReport& report); // flips, then collapses, as the settings ask

  SurfaceMesh Mesh;
  EvolverSettings Settings;
  const DistanceGrid* Field;
  Box Domain; // scaled
  double Scale;
  Vec3 Center;
  std::string Error;
  int Steps = 0;
  std::vector<Vec3> Y; // scaled positions
  std::vector<Vec3> VT;
  std::vector<double> Potential;
  std::unique_ptr<Solver> Linear;
};

// Signed volume enclosed by a closed, outward oriented surface.
double enclosedVolume(const SurfaceMesh& mesh, const std::vector<Vec3>& points);

} // namespace shrinkwrap

#endif
