// Speed of one evolution step (assembly, redistribution, three solves) on icospheres, and of the
// finest shrinking-sphere test of Section 4.2 end to end (2562 vertices, 384 steps), for both
// linear solvers: conjugate gradients on the symmetric form (default) and the paper's BiCGSTAB.
//   BenchEvolver [--steps N]
#include "Evolution/Evolver.h"
#include "Surface/Icosphere.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
using namespace shrinkwrap;
using Clock = std::chrono::steady_clock;

SurfaceMesh sphereMesh(int level)
{
  const TriangleSoup s = icosphere(level);
  SurfaceMesh mesh;
  SurfaceMesh::build(s.points, s.triangles, mesh);
  return mesh;
}

EvolverSettings mcf(int level, Redistribution r, LinearSolver solver)
{
  EvolverSettings s = EvolverSettings::paper();
  s.C1 = 1;
  s.C2 = 0;
  s.C = 0;
  s.timeStep = 0.01 / std::pow(4.0, level - 1); // the tables' time steps
  s.redistribution = r;
  s.solver = solver;
  s.solverTolerance = 1e-10;
  return s;
}

// Median milliseconds per step over `steps` steps (after one warm-up step).
double msPerStep(int level, Redistribution r, LinearSolver solver, int steps)
{
  const SurfaceMesh mesh = sphereMesh(level);
  Evolver evolver(mesh, mcf(level, r, solver));
  evolver.step();
  std::vector<double> times;
  for (int k = 0; k < steps; ++k)
  {
    const auto start = Clock::now();
    evolver.step();
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// The finest sphere test: 384 steps on level 4, seconds, and its error norm.
std::pair<double, double> finestSphere(Redistribution r, LinearSolver solver)
{
  const SurfaceMesh mesh = sphereMesh(4);
  const auto start = Clock::now();
  Evolver evolver(mesh, mcf(4, r, solver));
  double sum = 0;
  for (int k = 1; k <= 384; ++k)
  {
    const SurfaceGeometry before = evolver.geometry();
    evolver.step();
    const std::vector<Vec3> x = evolver.positions();
    const double radius = std::sqrt(1.0 - 4.0 * k * 1.5625e-4);
    for (int i = 0; i < mesh.vertexCount(); ++i)
    {
      sum += 1.5625e-4 * std::pow(x[i].norm() - radius, 2) * before.coVolume[i];
    }
  }
  return { std::chrono::duration<double>(Clock::now() - start).count(), std::sqrt(sum) };
}
} // namespace

int main(int argc, char* argv[])
{
  const int steps = argc > 2 && std::string(argv[1]) == "--steps" ? std::atoi(argv[2]) : 20;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [&] {
    std::printf("| vertices | CG, none | CG, volume | BiCGSTAB, none | BiCGSTAB, volume "
                "|\n|---|---|---|---|---|\n");
    for (int level = 3; level <= 6; ++level)
    {
      std::printf("| %lld | %.2f ms | %.2f ms | %.2f ms | %.2f ms |\n", icosphereVertexCount(level),
        msPerStep(level, Redistribution::None, LinearSolver::ConjugateGradient, steps),
        msPerStep(level, Redistribution::Volume, LinearSolver::ConjugateGradient, steps),
        msPerStep(level, Redistribution::None, LinearSolver::BiCGSTAB, steps),
        msPerStep(level, Redistribution::Volume, LinearSolver::BiCGSTAB, steps));
      std::fflush(stdout);
    }
    std::printf("\nFinest shrinking-sphere test (2562 vertices, 384 steps, error norm of Table "
                "2/3), end to end:\n\n");
    std::printf("| solver | redistribution | seconds | err |\n|---|---|---|---|\n");
    for (const auto solver : { LinearSolver::ConjugateGradient, LinearSolver::BiCGSTAB })
    {
      for (const auto r : { Redistribution::None, Redistribution::Volume })
      {
        const auto [seconds, err] = finestSphere(r, solver);
        std::printf("| %s | %s | %.3f | %.4e |\n",
          solver == LinearSolver::BiCGSTAB ? "BiCGSTAB" : "CG",
          r == Redistribution::Volume ? "volume" : "none", seconds, err);
      }
    }
  });
  return 0;
}
