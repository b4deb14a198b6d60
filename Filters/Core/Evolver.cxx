#include "Evolver.h"
#include "Parallel.h"

#include "EdgeFlips.h"
#include "TangentialRedistribution.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace shrinkwrap
{

namespace
{
template <typename Iterative, typename Matrix, typename Column, typename Result>
bool solveColumn(Iterative& solver, const Matrix& matrix, double tolerance, const Column& rhs, const Column& guess,
  Result&& solution)
{
  solver.setTolerance(tolerance);
  solver.compute(matrix);
  solution = solver.solveWithGuess(rhs, guess);
  return solver.info() == Eigen::Success;
}
} // namespace

// The system matrix keeps its sparsity pattern for the whole evolution; only values change.
struct Evolver::Solver
{
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  Matrix matrix;
  std::vector<int> diagonal; // value index of (i, i)
  std::vector<int> offDiagonal; // value index of (i, ring(p)), per one-ring entry p
  std::array<Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper>, 3> cg;
  std::array<Eigen::BiCGSTAB<Matrix>, 3> bicgstab;

  // The pattern straight from the one-rings (rebuilt after every round of edge flips): row i holds
  // i and its neighbours, in column order.
  explicit Solver(const SurfaceMesh& mesh)
  {
    const int nv = mesh.vertexCount();
    this->matrix.resize(nv, nv);
    this->matrix.resizeNonZeros(mesh.ringEnd(nv - 1) + nv);
    int* outer = this->matrix.outerIndexPtr();
    int* inner = this->matrix.innerIndexPtr();
    std::fill(this->matrix.valuePtr(), this->matrix.valuePtr() + this->matrix.nonZeros(), 0.0);
    this->diagonal.resize(nv);
    this->offDiagonal.resize(mesh.ringEnd(nv - 1));
    std::vector<std::pair<int, int>> row; // (column, ring entry or -1 for the diagonal)
    outer[0] = 0;
    for (int i = 0; i < nv; ++i)
    {
      row.assign(1, { i, -1 });
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        row.emplace_back(mesh.ring(p), p);
      }
      std::sort(row.begin(), row.end());
      for (std::size_t k = 0; k < row.size(); ++k)
      {
        const int at = outer[i] + static_cast<int>(k);
        inner[at] = row[k].first;
        (row[k].second < 0 ? this->diagonal[i] : this->offDiagonal[row[k].second]) = at;
      }
      outer[i + 1] = outer[i] + static_cast<int>(row.size());
    }
  }
};

Evolver::Evolver(const SurfaceMesh& mesh, const EvolverSettings& settings, const DistanceGrid* field,
  const Box& domain, double scale, const Vec3& center)
  : Mesh(mesh)
  , Settings(settings)
  , Field(field && !field->empty() ? field : nullptr)
  , Scale(scale)
  , Center(center)
{
  std::ostringstream why;
  if (!(settings.timeStep > 0) || !std::isfinite(settings.timeStep))
    why << "the time step must be positive";
  else if (!(scale > 0) || !std::isfinite(scale))
    why << "the scale must be positive";
  else if (settings.C1 < 0 || settings.C2 < 0 || settings.C < 0 || settings.D < 0)
    why << "C1, C2, C and D must not be negative";
  else if (settings.omegaAngle < 0 || settings.omegaVolume < 0 || settings.rhoA < 0)
    why << "the redistribution weights must not be negative";
  else if (mesh.vertexCount() < 4)
    why << "the surface is empty";
  this->Error = why.str();
  if (!this->Error.empty())
  {
    return;
  }
  if (!domain.empty())
  {
    this->Domain.min = scale * (domain.min - center);
    this->Domain.max = scale * (domain.max - center);
  }
  this->Y.reserve(mesh.vertexCount());
  for (const Vec3& x : mesh.initialPoints())
  {
    this->Y.push_back(scale * (x - center));
  }
  this->VT.assign(mesh.vertexCount(), Vec3::Zero());
  this->Linear = std::make_unique<Solver>(mesh);
}

Evolver::~Evolver() = default;

void Evolver::sampleField(std::vector<double>& d, std::vector<Vec3>& grad) const
{
  const int nv = this->Mesh.vertexCount();
  d.assign(nv, 0.0);
  grad.assign(nv, Vec3::Zero());
  if (!this->Field)
  {
    return;
  }
  parallelFor(0, nv, [&](int b, int e) {
    for (int i = b; i < e; ++i)
    {
      const DistanceSample s = this->Field->sample(this->Center + this->Y[i] / this->Scale);
      d[i] = this->Scale * s.value; // distances scale with the geometry; gradients do not
      grad[i] = s.gradient;
    }
  });
}

StepReport Evolver::check(const std::vector<Vec3>& y) const
{
  StepReport report;
  report.step = this->Steps + 1;
  std::ostringstream message;
  for (int i = 0; i < static_cast<int>(y.size()); ++i)
  {
    if (!y[i].allFinite())
    {
      message << "vertex " << i << " became NaN at step " << report.step;
      report.failure = Failure::NotANumber;
      report.where = i;
      report.message = message.str();
      return report;
    }
    if (!this->Domain.empty() && (this->Domain.squaredDistance(y[i]) > 0))
    {
      message << "vertex " << i << " left the domain at step " << report.step;
      report.failure = Failure::LeftDomain;
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

StepReport Evolver::step()
{
  const int nv = this->Mesh.vertexCount();
  const EvolverSettings& s = this->Settings;
  const double tau = s.timeStep;
  SurfaceGeometry g;
  computeGeometry(this->Mesh, this->Y, g);
  std::vector<double> d;
  std::vector<Vec3> grad;
  this->sampleField(d, grad);

  // Control functions, eqs. (3) and (4).
  std::vector<double> eps(nv), eta(nv);
  for (int i = 0; i < nv; ++i)
  {
    eps[i] = s.C2 > 0 ? s.C1 * (1.0 - std::exp(-d[i] * d[i] / s.C2)) : s.C1;
    const double alignment = grad[i].dot(g.normal[i]);
    eta[i] = s.C * d[i] * (-alignment - s.D * std::sqrt(std::max(0.0, 1.0 - alignment * alignment)));
  }

  // Tangential velocity (Section 2.3).
  std::vector<Vec3> vt(nv, Vec3::Zero());
  StepReport report;
  report.step = this->Steps + 1;
  if (s.redistribution == Redistribution::Angle)
  {
    std::vector<double> weights(nv, s.omegaAngle);
    if (this->Field && s.distanceWeight)
    {
      for (int i = 0; i < nv; ++i)
      {
        weights[i] *= s.rhoA * (1.0 - std::exp(-d[i] * d[i])); // rho(d), eq. (10)
      }
    }
    angleVelocities(this->Mesh, this->Y, g, weights, vt);
  }
  else if (s.redistribution == Redistribution::Volume)
  {
    std::vector<Vec3> normalVelocity(nv);
    for (int i = 0; i < nv; ++i)
    {
      normalVelocity[i] = eps[i] * g.curvature[i] + eta[i] * g.normal[i];
    }
    const VolumeRedistribution settings{ s.omegaVolume, s.volumePerArea, s.solverTolerance };
    if (!volumeVelocities(this->Mesh, this->Y, g, normalVelocity, settings, this->Potential, vt))
    {
      report.failure = Failure::SolverFailed;
      report.message = "the redistribution potential did not converge at step " + std::to_string(report.step);
      return report;
    }
  }

  // Assemble: the symmetric form multiplies row i by |V_i| / eps_i.
  Solver& L = *this->Linear;
  double* values = L.matrix.valuePtr();
  Eigen::MatrixXd rhs(nv, 3), guess(nv, 3);
  const bool symmetric = s.solver == LinearSolver::ConjugateGradient;
  for (int i = 0; i < nv; ++i)
  {
    const double e = std::max(eps[i], 1e-14);
    const double rowScale = symmetric ? 1.0 : e / g.coVolume[i]; // multiplies tau w_ij
    const double identity = symmetric ? g.coVolume[i] / e : 1.0;
    double sum = 0;
    for (int p = this->Mesh.ringBegin(i); p < this->Mesh.ringEnd(i); ++p)
    {
      values[L.offDiagonal[p]] = -tau * rowScale * g.weight[p];
      sum += g.weight[p];
    }
    values[L.diagonal[i]] = identity + tau * rowScale * sum;
    const Vec3 b = identity * (this->Y[i] + tau * eta[i] * g.normal[i] + tau * vt[i]);
    rhs.row(i) = b.transpose();
    guess.row(i) = this->Y[i].transpose();
  }
  // The three coordinates are independent systems with one matrix: solved side by side, one solver
  // object each (a solve writes its own iteration counts).
  Eigen::MatrixXd solution(nv, 3);
  std::array<bool, 3> solved{};
  parallelFor(0, 3, 1, [&](int b, int e) {
    for (int c = b; c < e; ++c)
    {
      if (symmetric)
      {
        solved[c] = solveColumn(L.cg[c], L.matrix, s.solverTolerance, rhs.col(c), guess.col(c), solution.col(c));
      }
      else
      {
        solved[c] =
          solveColumn(L.bicgstab[c], L.matrix, s.solverTolerance, rhs.col(c), guess.col(c), solution.col(c));
      }
    }
  });
  const bool converged = solved[0] && solved[1] && solved[2];
  std::vector<Vec3> next(nv);
  for (int i = 0; i < nv; ++i)
  {
    next[i] = solution.row(i).transpose();
  }
  report = this->check(next);
  if (report.ok() && !converged)
  {
    report.failure = Failure::SolverFailed;
    report.message = "the linear solver did not converge at step " + std::to_string(report.step);
  }
  // A triangle that degenerated within the step may still be mended by flips and collapses: the step
  // fails only if they cannot mend it, and then the last good surface is restored.
  const bool mendable =
    report.failure == Failure::DegenerateTriangle && converged && (s.edgeFlips || s.edgeCollapses);
  if (!report.ok() && !mendable)
  {
    return report;
  }
  std::vector<Vec3> goodY, goodVT;
  std::vector<std::array<int, 3>> goodTriangles;
  if (mendable)
  {
    goodY = this->Y;
    goodVT = this->VT;
    goodTriangles = this->Mesh.triangles();
  }
  this->Y.swap(next);
  this->VT.swap(vt);
  this->adjustConnectivity(report);
  if (mendable)
  {
    const StepReport mended = this->check(this->Y);
    if (!mended.ok())
    {
      this->reset(goodY, goodTriangles);
      this->VT.swap(goodVT);
      return mended;
    }
    report = StepReport{ Failure::None, mended.step, -1, {}, report.flips, report.collapses, mended.smallestAngle };
  }
  ++this->Steps;
  return report;
}

void Evolver::adjustConnectivity(StepReport& report)
{
  const EvolverSettings& s = this->Settings;
  if (s.edgeFlips)
  {
    std::vector<std::array<int, 3>> triangles;
    report.flips = flipEdges(this->Mesh, this->Y, s.flips, triangles);
    if (report.flips > 0 && !this->reconnect(triangles))
    {
      report.flips = 0;
    }
  }
  // Degenerating triangles cluster where the surface folds, and a pass collapses one edge per
  // neighbourhood: passes repeat while they find edges to collapse.
  const bool degenerating = !(report.smallestAngle >= s.collapses.maxAngle);
  for (int pass = 0; s.edgeCollapses && degenerating && pass < s.collapses.maxPasses; ++pass)
  {
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> kept;
    const int collapses = collapseEdges(this->Mesh, this->Y, s.collapses, points, triangles, kept);
    if (collapses == 0 || !this->reset(points, triangles))
    {
      break;
    }
    std::vector<Vec3> velocity;
    for (int v : kept)
    {
      velocity.push_back(this->VT[v]);
    }
    this->VT.swap(velocity);
    report.collapses += collapses;
  }
}

std::vector<Vec3> Evolver::positionsOf(const std::vector<Vec3>& state) const
{
  std::vector<Vec3> x;
  x.reserve(state.size());
  for (const Vec3& y : state)
  {
    x.push_back(this->Center + y / this->Scale);
  }
  return x;
}

bool Evolver::restart(const std::vector<Vec3>& state, const std::vector<std::array<int, 3>>* triangles, int steps)
{
  if (triangles ? !this->reset(state, *triangles) : state.size() != this->Y.size())
  {
    return false;
  }
  this->Y = state; // reset has set it already when the triangles came along
  this->Steps = steps;
  this->Potential.clear();
  this->VT.assign(this->Y.size(), Vec3::Zero());
  return true;
}

bool Evolver::reset(const std::vector<Vec3>& y, const std::vector<std::array<int, 3>>& triangles)
{
  SurfaceMesh mesh;
  std::string error;
  if (!SurfaceMesh::build(y, triangles, mesh, error))
  {
    return false;
  }
  if (y.size() != this->Y.size())
  {
    this->Potential.clear(); // a warm start for the same vertices only
  }
  this->Y = y;
  this->Mesh = std::move(mesh);
  this->Linear = std::make_unique<Solver>(this->Mesh);
  return true;
}

bool Evolver::reconnect(const std::vector<std::array<int, 3>>& triangles)
{
  return this->reset(this->Y, triangles);
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
  v.reserve(this->VT.size());
  for (const Vec3& u : this->VT)
  {
    v.push_back(this->Scale * u);
  }
  return v;
}

double enclosedVolume(const SurfaceMesh& mesh, const std::vector<Vec3>& x)
{
  double volume = 0;
  for (const auto& t : mesh.triangles())
  {
    volume += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
  }
  return volume / 6.0;
}

} // namespace shrinkwrap
