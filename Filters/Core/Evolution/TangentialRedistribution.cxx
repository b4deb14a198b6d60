#include "Evolution/TangentialRedistribution.h"
#include "Common/Parallel.h"
#include "Surface/CotanLaplacian.h"

#include <Eigen/IterativeLinearSolvers>

namespace shrinkwrap
{

namespace
{
Vec3 tangential(const Vec3& v, const Vec3& n)
{
  return v - v.dot(n) * n;
}
} // namespace

void angleVelocities(const SurfaceMesh& mesh, const std::vector<Vec3>& x, const SurfaceGeometry& g,
  const std::vector<double>& weights, std::vector<Vec3>& velocity)
{
  const int nv = mesh.vertexCount();
  velocity.resize(nv);
  parallelFor(0, nv, kCheapGrain, [&](int b, int e) {
    for (int i = b; i < e; ++i)
    {
      Vec3 sum = Vec3::Zero();
      for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
      {
        const Vec3 a = x[mesh.ring(p)] - x[i], c = x[mesh.ring(mesh.next(i, p))] - x[i];
        const double la = a.norm(), lc = c.norm();
        if (la > 0 && lc > 0)
        {
          sum += (1.0 + a.dot(c) / (la * lc)) * (a + c);
        }
      }
      velocity[i] = tangential(weights[i] / mesh.valence(i) * sum, g.normal[i]);
    }
  });
}

bool volumeVelocities(const SurfaceMesh& mesh, const std::vector<Vec3>& x, const SurfaceGeometry& g,
  const std::vector<Vec3>& normalVelocity, const VolumeRedistribution& settings,
  std::vector<double>& potential, std::vector<Vec3>& velocity)
{
  const int nv = mesh.vertexCount();
  // Right-hand side of the Poisson problem for psi.
  std::vector<double> hv(nv);
  double mean = 0;
  for (int i = 0; i < nv; ++i)
  {
    hv[i] = g.curvature[i].dot(normalVelocity[i]);
    mean += g.coVolume[i] * hv[i];
  }
  mean /= g.area;
  Eigen::VectorXd rhs(nv);
  for (int i = 0; i < nv; ++i)
  {
    rhs[i] = g.coVolume[i] * (hv[i] - mean) + settings.omega * (g.area / nv - g.coVolume[i]);
  }
  // The area element changes as d(dA)/dt = (-h.v_N + div v_T) dA (h = Laplace-Beltrami of F), so
  // co-volumes relax towards A/N_V when the integral of div grad psi over V_i, sum_j w_ij (psi_j -
  // psi_i), equals the right-hand side. The sum_j w_ij (psi_i - psi_j) with v_T = +grad psi
  // drives them apart (measured: max/min co-volume 79 -> 26000 on an MCF ellipsoid); hence the
  // minus sign.
  rhs = -rhs;
  // The cotangent Laplacian with psi_0 = 0.
  CotanLaplacian laplacian(mesh);
  laplacian.assemble(mesh, g.weight, [](int) { return std::make_pair(0.0, 1.0); });
  laplacian.pin(mesh, 0);
  rhs[0] = 0;
  Eigen::ConjugateGradient<CotanLaplacian::Matrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(settings.tolerance);
  cg.setMaxIterations(4 * nv);
  cg.compute(laplacian.matrix());
  Eigen::VectorXd guess = Eigen::VectorXd::Zero(nv);
  if (static_cast<int>(potential.size()) == nv)
  {
    guess = Eigen::Map<const Eigen::VectorXd>(potential.data(), nv);
  }
  const Eigen::VectorXd psi = cg.solveWithGuess(rhs, guess);
  if (cg.info() != Eigen::Success || !psi.allFinite())
  {
    return false;
  }
  potential.assign(psi.data(), psi.data() + nv);

  // v_T: the piecewise-linear gradient of psi integrated over each co-volume (a third of each
  // incident triangle), divided by |V_i| when perArea.
  const auto& tris = mesh.triangles();
  std::vector<Vec3> triangleGradient(mesh.triangleCount());
  for (int t = 0; t < mesh.triangleCount(); ++t)
  {
    const auto& v = tris[t];
    const Vec3 n = (x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]); // |n| = 2 |T|
    const double n2 = n.squaredNorm();
    Vec3 grad = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 edge = x[v[(k + 2) % 3]] - x[v[(k + 1) % 3]]; // opposite vertex k
      grad += psi[v[k]] * n.cross(edge);
    }
    triangleGradient[t] = n2 > 0 ? Vec3(grad / n2) : Vec3::Zero();
  }
  velocity.resize(nv);
  for (int i = 0; i < nv; ++i)
  {
    Vec3 integral = Vec3::Zero();
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      integral +=
        g.triangleArea[mesh.ringTriangle(p)] / 3.0 * triangleGradient[mesh.ringTriangle(p)];
    }
    const Vec3 v =
      settings.perArea && g.coVolume[i] > 0 ? Vec3(integral / g.coVolume[i]) : integral;
    velocity[i] = tangential(v, g.normal[i]);
  }
  return true;
}

} // namespace shrinkwrap
