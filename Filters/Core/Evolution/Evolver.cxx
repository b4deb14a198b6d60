#include "Evolution/Evolver.h"

#include "Common/Parallel.h"
#include "Evolution/ControlFunctions.h"
#include "Evolution/TangentialRedistribution.h"
#include "Remeshing/CheckedEdits.h"
#include "Remeshing/EdgeFlips.h"
#include "Surface/CotanLaplacian.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceGeometry.h"

#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shrinkwrap
{

namespace
{
template <typename Iterative, typename Matrix, typename Column, typename Result>
bool solveColumn(Iterative& solver, const Matrix& matrix, double tolerance, const Column& rhs,
  const Column& guess, Result&& solution)
{
  solver.setTolerance(tolerance);
  // A step's system converges in one or two iterations from the last positions (the seven benchmark
  // meshes, L alone and adaptive); one that has not in 500 is hopeless (a fuzzed case of 43,000
  // vertices with thin triangles ran Eigen's default 2 n for 80 s), and the step fails as unsolved.
  solver.setMaxIterations(500);
  solver.compute(matrix);
  solution = solver.solveWithGuess(rhs, guess);
  return solver.info() == Eigen::Success;
}

Status validate(const EvolverSettings& settings, double scale, const SurfaceMesh& mesh)
{
  if (!(settings.timeStep > 0) || !std::isfinite(settings.timeStep))
    return Status::failure("the time step must be positive");
  if (!(scale > 0) || !std::isfinite(scale))
    return Status::failure("the scale must be positive");
  if (settings.C1 < 0 || settings.C2 < 0 || settings.C < 0 || settings.D < 0)
    return Status::failure("C1, C2, C and D must not be negative");
  if (settings.omegaAngle < 0 || settings.omegaVolume < 0 || settings.rhoA < 0)
    return Status::failure("the redistribution weights must not be negative");
  if (settings.remeshing &&
    !(settings.remeshing->targetLength > 0 && std::isfinite(settings.remeshing->targetLength)))
    return Status::failure("the target edge length must be positive");
  if (mesh.vertexCount() < 4)
    return Status::failure("the surface is empty");
  return {};
}
} // namespace

// The system matrix (eq. (5)) keeps its sparsity pattern while the connectivity does; the three
// coordinates are solved side by side, one solver object each (a solve writes its own counts).
struct Evolver::Solver
{
  explicit Solver(const SurfaceMesh& mesh)
    : laplacian(mesh)
  {
  }
  CotanLaplacian laplacian;
  std::array<Eigen::ConjugateGradient<CotanLaplacian::Matrix, Eigen::Lower | Eigen::Upper>, 3> cg;
  std::array<Eigen::BiCGSTAB<CotanLaplacian::Matrix>, 3> bicgstab;
};

// What the step's terms are made of: the geometry (Section 2.2) and, per vertex, d, grad d and the
// control functions eps and eta (eqs. (3), (4)).
struct Evolver::Controls
{
  SurfaceGeometry g;
  std::vector<double> d, eps, eta;
  std::vector<Vec3> grad;
};

Evolver::Evolver(const SurfaceMesh& mesh, const EvolverSettings& settings,
  const TargetDistance* field, const Box& domain, double scale, const Vec3& center)
  : Mesh(mesh)
  , Settings(settings)
  , Field(field && !field->empty() ? field : nullptr)
  , Scale(scale)
  , Center(center)
  , Valid(validate(settings, scale, mesh))
{
  if (!this->Valid)
  {
    return;
  }
  if (!domain.empty())
  {
    this->Domain.min = scale * (domain.min - center);
    this->Domain.max = scale * (domain.max - center);
  }
  for (Vec3& x : this->Mesh.points())
  {
    x = scale * (x - center);
  }
  this->velocity().assign(mesh.vertexCount(), Vec3::Zero());
  this->Linear = std::make_unique<Solver>(this->Mesh);
  if (settings.rims.cover && settings.remeshing && this->Field && this->Field->exact())
  {
    this->RimSamples = rimSamples(this->Field->exact()->rims(settings.rims.creaseAngle),
      settings.rims.spacing * settings.remeshing->targetLength);
  }
}

Evolver::~Evolver() = default;

Evolver::Controls Evolver::controls() const
{
  const std::vector<Vec3>& y = this->Mesh.points();
  const int nv = this->Mesh.vertexCount();
  const EvolverSettings& s = this->Settings;
  Controls c;
  computeGeometry(this->Mesh, y, c.g);
  c.d.assign(nv, 0.0);
  c.grad.assign(nv, Vec3::Zero());
  // Asked between the phases: a stopped step discards the controls.
  if (this->stopped())
  {
    return c;
  }
  if (this->Field)
  {
    parallelFor(0, nv, [&](int b, int e) {
      for (int i = b; i < e; ++i)
      {
        const DistanceSample sample = this->Field->sample(this->Center + y[i] / this->Scale);
        c.d[i] = this->Scale * sample.value; // distances scale with the geometry; gradients do not
        c.grad[i] = sample.gradient;
      }
    });
  }
  if (this->stopped())
  {
    return c;
  }
  c.eps.resize(nv);
  c.eta.resize(nv);
  // The landing needs the remeshing's near-equilateral rings (h measures curvature only there), and
  // none at the vertices that hold the target's rims (a fold around a sheet's edge is no curvature
  // of the target's: landed out, the folds would leave the rims out).
  const bool fit = this->Field && s.facetFit != 0 && s.remeshing;
  const std::vector<double> rimVertices = fit && !this->RimSamples.empty()
    ? rimHolds(this->Mesh, this->scaledRimSamples(), s.remeshing->targetLength * this->Scale)
    : std::vector<double>();
  for (int i = 0; i < nv; ++i)
  {
    const bool holds = !rimVertices.empty() && rimVertices[i] > 0;
    const double landing =
      fit && !holds ? 0.25 * s.facetFit * this->heightOverRing(i, c.g.normal[i]) : 0.0;
    c.eps[i] = diffusion(c.d[i], s.C1, s.C2);
    c.eta[i] = advection(c.d[i] - landing, c.grad[i].dot(c.g.normal[i]), s.C, s.D);
  }
  return c;
}

double Evolver::heightOverRing(int i, const Vec3& normal) const
{
  const std::vector<Vec3>& y = this->Mesh.points();
  const int begin = this->Mesh.ringBegin(i), end = this->Mesh.ringEnd(i);
  if (end <= begin)
  {
    return 0;
  }
  Vec3 centroid = Vec3::Zero();
  double l2 = 0;
  for (int p = begin; p < end; ++p)
  {
    centroid += y[this->Mesh.ring(p)];
    l2 += (y[this->Mesh.ring(p)] - y[i]).squaredNorm();
  }
  // At most half the ring's mean edge l, so a landing of h / 4 stays within l / 8, the sagitta
  // where the surface's radius is one edge: where the wrap folds around a tip or a fin's edge, its
  // height over the ring is no curvature of the target's.
  const double cap = 0.5 * std::sqrt(l2 / (end - begin));
  return std::clamp(normal.dot(y[i] - centroid / (end - begin)), -cap, cap);
}

// Section 2.3; false if the volume redistribution's potential did not converge.
bool Evolver::tangentialVelocities(const Controls& c, std::vector<Vec3>& vt)
{
  const int nv = this->Mesh.vertexCount();
  const EvolverSettings& s = this->Settings;
  vt.assign(nv, Vec3::Zero());
  if (s.redistribution == Redistribution::Angle)
  {
    std::vector<double> weights(nv, s.omegaAngle);
    if (this->Field && s.distanceWeight)
    {
      for (int i = 0; i < nv; ++i)
      {
        weights[i] *= redistributionWeight(c.d[i], s.rhoA);
      }
    }
    angleVelocities(this->Mesh, this->Mesh.points(), c.g, weights, vt);
  }
  else if (s.redistribution == Redistribution::Volume)
  {
    std::vector<Vec3> normalVelocity(nv);
    for (int i = 0; i < nv; ++i)
    {
      normalVelocity[i] = c.eps[i] * c.g.curvature[i] + c.eta[i] * c.g.normal[i];
    }
    const VolumeRedistribution settings{ s.omegaVolume, s.volumePerArea, s.solverTolerance };
    return volumeVelocities(
      this->Mesh, this->Mesh.points(), c.g, normalVelocity, settings, this->Potential, vt);
  }
  return true;
}

// Eq. (5), per vertex i and coordinate:
//   (1 + tau eps_i/|V_i| sum_j w_ij) F_i - tau eps_i/|V_i| sum_j w_ij F_j = F_i^old + tau eta_i N_i
//   + tau v_T,i;
// the symmetric form (conjugate gradients) multiplies row i by |V_i| / eps_i. False if a solve did
// not converge.
bool Evolver::solve(const Controls& c, const std::vector<Vec3>& vt, std::vector<Vec3>& next)
{
  const int nv = this->Mesh.vertexCount();
  const EvolverSettings& s = this->Settings;
  const std::vector<Vec3>& y = this->Mesh.points();
  const double tau = s.timeStep;
  const bool symmetric = s.solver == LinearSolver::ConjugateGradient;
  auto rowTerms = [&](int i) {
    const double e = std::max(c.eps[i], 1e-14);
    const double rowScale = symmetric ? 1.0 : e / c.g.coVolume[i]; // multiplies tau w_ij
    const double identity = symmetric ? c.g.coVolume[i] / e : 1.0;
    return std::make_pair(identity, tau * rowScale);
  };
  Solver& L = *this->Linear;
  L.laplacian.assemble(this->Mesh, c.g.weight, rowTerms);
  Eigen::MatrixXd rhs(nv, 3), guess(nv, 3);
  for (int i = 0; i < nv; ++i)
  {
    const Vec3 b = rowTerms(i).first * (y[i] + tau * c.eta[i] * c.g.normal[i] + tau * vt[i]);
    rhs.row(i) = b.transpose();
    guess.row(i) = y[i].transpose();
  }
  Eigen::MatrixXd solution(nv, 3);
  std::array<bool, 3> solved{};
  const auto& matrix = L.laplacian.matrix();
  // A column's solve on a few thousand vertices is shorter than starting a thread (Parallel.h).
  parallelFor(0, 3, nv < kCheapGrain ? 3 : 1, [&](int b, int e) {
    for (int k = b; k < e; ++k)
    {
      solved[k] = symmetric
        ? solveColumn(L.cg[k], matrix, s.solverTolerance, rhs.col(k), guess.col(k), solution.col(k))
        : solveColumn(
            L.bicgstab[k], matrix, s.solverTolerance, rhs.col(k), guess.col(k), solution.col(k));
    }
  });
  next.resize(nv);
  for (int i = 0; i < nv; ++i)
  {
    next[i] = solution.row(i).transpose();
  }
  return solved[0] && solved[1] && solved[2];
}

StepReport Evolver::check(const std::vector<Vec3>& y) const
{
  StepReport report;
  report.step = this->Steps + 1;
  std::ostringstream message;
  for (int i = 0; i < static_cast<int>(y.size()); ++i)
  {
    const bool nan = !y[i].allFinite();
    if (nan || (!this->Domain.empty() && (this->Domain.squaredDistance(y[i]) > 0)))
    {
      message << "vertex " << i << (nan ? " became NaN" : " left the domain") << " at step "
              << report.step;
      report.failure = nan ? Failure::NotANumber : Failure::LeftDomain;
      report.where = i;
      report.message = message.str();
      return report;
    }
  }
  const SmallestAngle smallest = smallestAngle(this->Mesh, y);
  report.smallestAngle = smallest.angle;
  if (!(smallest.angle >= this->Settings.minAngle))
  {
    message << "triangle " << smallest.triangle << " degenerated (smallest angle " << smallest.angle
            << " rad) at step " << report.step;
    report.failure = Failure::DegenerateTriangle;
    report.where = smallest.triangle;
    report.message = message.str();
  }
  return report;
}

namespace
{
StepReport stoppedAt(int step)
{
  StepReport report;
  report.step = step;
  report.failure = Failure::Stopped;
  report.message = "stopped at step " + std::to_string(step);
  return report;
}
} // namespace

StepReport Evolver::step()
{
  // What a stopped step must leave as it was, beside the surface (which the caller restarts).
  const auto recent = this->RecentCrossings;
  const auto held = this->HeldNear;
  StepReport report = this->fullStep();
  if (report.failure == Failure::Stopped)
  {
    this->RecentCrossings = recent;
    this->HeldNear = held;
  }
  return report;
}

StepReport Evolver::fullStep()
{
  const Controls c = this->controls();
  if (this->stopped())
  {
    return stoppedAt(this->Steps + 1);
  }
  std::vector<Vec3> vt;
  if (!this->tangentialVelocities(c, vt))
  {
    StepReport report;
    report.step = this->Steps + 1;
    report.failure = Failure::SolverFailed;
    report.message =
      "the redistribution potential did not converge at step " + std::to_string(report.step);
    return report;
  }
  if (this->stopped())
  {
    return stoppedAt(this->Steps + 1);
  }
  std::vector<Vec3> next;
  const bool converged = this->solve(c, vt, next);
  if (this->stopped())
  {
    return stoppedAt(this->Steps + 1);
  }
  StepReport report = this->accept(next, vt, converged);
  return this->stopped() && report.ok() ? stoppedAt(this->Steps) : report;
}

// The new positions pass the checks, or a triangle that degenerated within the step is mended by
// flips and collapses; otherwise the step fails and the last good surface stays.
StepReport Evolver::accept(std::vector<Vec3>& next, std::vector<Vec3>& vt, bool converged)
{
  const EvolverSettings& s = this->Settings;
  const int held = s.holdBack && converged ? this->holdBack(next) : 0;
  StepReport report = this->check(next);
  report.held = held;
  if (report.ok() && !converged)
  {
    report.failure = Failure::SolverFailed;
    report.message = "the linear solver did not converge at step " + std::to_string(report.step);
  }
  const bool mendable =
    report.failure == Failure::DegenerateTriangle && converged && (s.edgeFlips || s.edgeCollapses);
  if (!report.ok() && !mendable)
  {
    return report;
  }
  SurfaceMesh good;
  if (mendable)
  {
    good = this->Mesh;
  }
  this->Mesh.points().swap(next);
  this->velocity().swap(vt);
  this->adjustConnectivity(report);
  if (mendable)
  {
    const int vanished = this->removeVanishedParts();
    const StepReport mended = this->check(this->Mesh.points());
    if (!mended.ok())
    {
      const int count = this->Mesh.vertexCount();
      this->Mesh = std::move(good);
      this->connectivityChanged(this->Mesh.vertexCount() == count);
      return mended;
    }
    const StepReport adjusted = report;
    report = mended;
    report.flips = adjusted.flips;
    report.collapses = adjusted.collapses;
    report.splits = adjusted.splits;
    report.held = adjusted.held;
    report.vanished = vanished;
  }
  report.rimMoves = this->coverRims();
  ++this->Steps;
  return report;
}

std::vector<Vec3> Evolver::scaledRimSamples() const
{
  std::vector<Vec3> samples;
  samples.reserve(this->RimSamples.size());
  for (const Vec3& x : this->RimSamples)
  {
    samples.push_back(this->Scale * (x - this->Center));
  }
  return samples;
}

int Evolver::coverRims()
{
  if (this->RimSamples.empty())
  {
    return 0;
  }
  const RimSettings& r = this->Settings.rims;
  const double length = this->Settings.remeshing->targetLength * this->Scale; // rims need it
  const std::vector<Vec3> samples = this->scaledRimSamples();
  const std::vector<Vec3> moves =
    rimMoves(this->Mesh, samples, r.tolerance * length, r.reach * length);
  // A move the hold-back refuses (it would cross the surface: near a rim both layers lie on the
  // sheet) is tried again at half its length, twice; one too small to change a coordinate is not
  // tried (it changes none at a share either).
  std::vector<char> pending(moves.size());
  int left = 0;
  for (std::size_t v = 0; v < moves.size(); ++v)
  {
    pending[v] = this->Mesh.points()[v] + moves[v] != this->Mesh.points()[v];
    left += pending[v];
  }
  int moved = 0;
  for (double share : { 1.0, 0.5, 0.25 })
  {
    if (left == 0)
    {
      break; // every sample covered (mostly so, once the wrap has landed): nothing to check
    }
    std::vector<Vec3> next = this->Mesh.points();
    for (std::size_t v = 0; v < moves.size(); ++v)
    {
      next[v] += pending[v] ? Vec3(share * moves[v]) : Vec3::Zero();
    }
    if (this->Settings.holdBack)
    {
      this->holdBack(next);
    }
    left = 0;
    for (std::size_t v = 0; v < moves.size(); ++v)
    {
      const bool done = pending[v] && next[v] != this->Mesh.points()[v];
      moved += done;
      pending[v] = pending[v] && !done;
      left += pending[v];
    }
    this->Mesh.points().swap(next);
  }
  return moved;
}

// Vertices stop where their step would break the surface: where it would cross itself
// (holdNewCrossings) or a triangle would degenerate below minAngle that did not before; held
// vertices keep their positions, and holding one can break another triangle, so the rounds repeat.
int Evolver::holdBack(std::vector<Vec3>& next)
{
  const std::vector<Vec3>& y = this->Mesh.points();
  const auto& triangles = this->Mesh.triangles();
  int held = 0;
  std::vector<int> crossed; // the triangles of the crossings vertices were held for
  for (int round = 0; round < 16 && !this->stopped(); ++round)
  {
    // holdNewCrossings settles its own rounds; only the vertices held for angles may make new
    // crossings.
    held += holdNewCrossings(y, next, triangles, &crossed, this->Stop);
    int moved = 0;
    for (const auto& t : triangles)
    {
      if (smallestAngleBelow(next[t[0]], next[t[1]], next[t[2]], this->Settings.minAngle) &&
        !smallestAngleBelow(y[t[0]], y[t[1]], y[t[2]], this->Settings.minAngle))
      {
        for (int v : t)
        {
          moved += next[v] != y[v];
          next[v] = y[v];
        }
      }
    }
    held += moved;
    if (moved == 0)
    {
      break;
    }
  }
  for (int t : crossed)
  {
    this->HeldNear.push_back(Box::around(y, triangles[t]));
  }
  return held;
}

StepReport Evolver::run(int n, const Progress& progress)
{
  StepReport report;
  for (int k = 0; k < n; ++k)
  {
    report = this->step();
    if (!report.ok() || !progress.report(static_cast<double>(k + 1) / n))
    {
      break;
    }
  }
  return report;
}

namespace
{
// Remeshing, flips, then the mending collapses, as the settings ask; counts into `report`.
Status editConnectivity(SurfaceMesh& mesh, const EvolverSettings& s, double scale,
  StepReport& report, const std::function<bool()>& stop)
{
  if (s.remeshing)
  {
    RemeshSettings r = *s.remeshing;
    r.targetLength *= scale;
    r.flips = s.flips;
    r.collapses = s.collapses;
    r.stop = stop;
    const RemeshReport remeshed = remesh(mesh, r);
    if (!remeshed.status)
    {
      return remeshed.status;
    }
    report.splits += remeshed.splits;
    report.collapses += remeshed.collapses;
    report.flips += remeshed.flips;
  }
  if (stop && stop())
  {
    return {};
  }
  if (s.edgeFlips)
  {
    report.flips += flipEdges(mesh, s.flips, stop);
  }
  if (stop && stop())
  {
    return {};
  }
  // Degenerating triangles cluster where the surface folds, and a pass collapses one edge per
  // neighbourhood: passes repeat while they find edges to collapse.
  const bool degenerating = !(report.smallestAngle >= s.collapses.maxAngle);
  for (int pass = 0;
       s.edgeCollapses && degenerating && pass < s.collapses.maxPasses && !(stop && stop()); ++pass)
  {
    const int collapses = collapseEdges(mesh, s.collapses);
    if (collapses == 0)
    {
      break;
    }
    report.collapses += collapses;
  }
  return {};
}
} // namespace

// The step's edits are checked once (CheckedEdits.h), as far as the settings guard them at all.
void Evolver::adjustConnectivity(StepReport& report)
{
  const EvolverSettings& s = this->Settings;
  const StepReport before = report;
  // The vertices that hold the target's rims stay in place in collapses (RimCoverage.h: rimHolds).
  if (!this->RimSamples.empty())
  {
    const double reach = s.rims.hold * s.remeshing->targetLength * this->Scale; // rims need it
    this->Mesh.addVertexProperty<double>(kAnchor, 0).values() =
      rimHolds(this->Mesh, this->scaledRimSamples(), reach);
  }
  Status edited;
  // A stopped edit reports no change: its trial is taken unchecked, and the step is stopped.
  auto edit = [&](SurfaceMesh& mesh, bool guarded, const std::vector<Box>& only) {
    EvolverSettings e = s;
    e.flips.avoidCrossings = guarded && s.flips.avoidCrossings;
    e.collapses.avoidCrossings = guarded && s.collapses.avoidCrossings;
    e.flips.guardOnlyIn = e.collapses.guardOnlyIn = only;
    report = before;
    edited = editConnectivity(mesh, e, this->Scale, report, this->Stop);
    return report.connectivityChanged() && !this->stopped();
  };
  if (s.flips.avoidCrossings || s.collapses.avoidCrossings)
  {
    // The edits behind a crossing lie within about two edges of it. Where the hold-back keeps two
    // parts apart, the edits would cross the other part at nearly every late step: while crossings
    // are recent, the edits there are guarded from the first try; not before, where guarding costs
    // more than the rare redo.
    const double reach = TriangleGrid::cellSizeFor(this->Mesh.points(), this->Mesh.triangles());
    std::vector<Box> recent;
    for (const auto& boxes : this->RecentCrossings)
    {
      recent.insert(recent.end(), boxes.begin(), boxes.end());
    }
    if (!recent.empty())
    {
      for (const Box& cell : cellsCovering(this->HeldNear, reach))
      {
        recent.push_back(cell.widened(reach));
      }
    }
    this->HeldNear.clear();
    this->RecentCrossings.push_back(editCheckedOnce(this->Mesh, reach, recent, edit, this->Stop));
    if (this->RecentCrossings.size() > kRememberedSteps)
    {
      this->RecentCrossings.pop_front();
    }
  }
  else
  {
    this->HeldNear.clear();
    edit(this->Mesh, false, {});
  }
  this->Mesh.removeVertexProperty(kAnchor);
  if (!edited)
  {
    report.failure = Failure::EditFailed;
    report.message =
      "the remeshing failed at step " + std::to_string(report.step) + ": " + edited.message();
  }
  if (report.connectivityChanged() && !this->stopped()) // a stopped step's surface is discarded
  {
    this->connectivityChanged(report.splits == 0 && report.collapses == 0);
  }
}

namespace
{
// Parts of the surface this small that fold have vanished (Evolver::removeVanishedParts).
constexpr int kVanishedVertices = 12;

// Whether the part of `mesh` that holds v has at most `limit` vertices (those seen are marked).
bool smallPart(const SurfaceMesh& mesh, int v, int limit, std::vector<char>& seen)
{
  std::vector<int> part = { v };
  seen[v] = 1;
  for (std::size_t k = 0; k < part.size() && static_cast<int>(part.size()) <= limit; ++k)
  {
    for (int p = mesh.ringBegin(part[k]); p < mesh.ringEnd(part[k]); ++p)
    {
      if (const int j = mesh.ring(p); !seen[j])
      {
        seen[j] = 1;
        part.push_back(j);
      }
    }
  }
  return static_cast<int>(part.size()) <= limit;
}
} // namespace

int Evolver::removeVanishedParts()
{
  const std::vector<Vec3>& y = this->Mesh.points();
  std::vector<char> seen(y.size(), 0);
  std::vector<int> vanished; // a vertex of each part
  for (const auto& t : this->Mesh.triangles())
  {
    if (!seen[t[0]] && smallestAngleBelow(y[t[0]], y[t[1]], y[t[2]], this->Settings.minAngle) &&
      smallPart(this->Mesh, t[0], kVanishedVertices, seen))
    {
      vanished.push_back(t[0]);
    }
  }
  for (int v : vanished)
  {
    this->Mesh.removePart(v);
  }
  if (vanished.empty() || !this->Mesh.commit())
  {
    return 0; // on failure the mesh is as it was (commit() restores it)
  }
  this->connectivityChanged(false);
  return static_cast<int>(vanished.size());
}

void Evolver::connectivityChanged(bool sameVertices)
{
  if (!sameVertices)
  {
    this->Potential.clear(); // a warm start for the same vertices only
  }
  this->Linear = std::make_unique<Solver>(this->Mesh);
}

std::vector<Vec3> unscaled(const std::vector<Vec3>& state, double scale, const Vec3& center)
{
  std::vector<Vec3> x;
  x.reserve(state.size());
  for (const Vec3& y : state)
  {
    x.push_back(center + y / scale);
  }
  return x;
}

std::vector<Vec3> Evolver::positionsOf(const std::vector<Vec3>& state) const
{
  return unscaled(state, this->Scale, this->Center);
}

bool Evolver::restart(const std::vector<Vec3>& state,
  const std::vector<std::array<int, 3>>* triangles, int steps, double scale)
{
  if (triangles)
  {
    SurfaceMesh mesh;
    if (!SurfaceMesh::build(state, *triangles, mesh))
    {
      return false;
    }
    const int count = this->Mesh.vertexCount();
    this->Mesh = std::move(mesh);
    this->connectivityChanged(this->Mesh.vertexCount() == count);
  }
  else if (state.size() != this->Mesh.points().size())
  {
    return false;
  }
  if (scale > 0 && scale != this->Scale)
  {
    this->setScale(scale);
  }
  this->Mesh.points() = state;
  this->Steps = steps;
  this->Potential.clear();
  this->RecentCrossings.clear(); // crossings of a surface no longer held
  this->HeldNear.clear();
  this->velocity().assign(state.size(), Vec3::Zero());
  return true;
}

Status Evolver::edit(const std::function<void(SurfaceMesh&)>& change)
{
  const int count = this->Mesh.vertexCount();
  change(this->Mesh);
  Status status = this->Mesh.commit();
  this->connectivityChanged(this->Mesh.vertexCount() == count);
  return status;
}

void Evolver::setScale(double scale)
{
  const double ratio = scale / this->Scale;
  for (Vec3& y : this->Mesh.points())
  {
    y *= ratio;
  }
  this->Domain.min *= ratio;
  this->Domain.max *= ratio;
  this->Scale = scale;
  this->Potential.clear();
}

SurfaceGeometry Evolver::geometry() const
{
  SurfaceGeometry g;
  computeGeometry(this->Mesh, this->positions(), g);
  return g;
}

std::vector<Vec3> Evolver::tangentialVelocity() const
{
  // y = phi x and t_scaled = phi^2 t, so dx/dt = phi dy/dt_scaled.
  std::vector<Vec3> v;
  const std::vector<Vec3> vt = this->Mesh.vertexValues<Vec3>(kVelocity);
  v.reserve(vt.size());
  for (const Vec3& u : vt)
  {
    v.push_back(this->Scale * u);
  }
  return v;
}

} // namespace shrinkwrap
