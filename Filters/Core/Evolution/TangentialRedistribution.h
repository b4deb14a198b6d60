// Tangential velocities v_T that keep the evolving mesh well shaped (paper Section 2.3).
//  - Angle-based (Medl'a et al. [5]): v_T,i = proj_T( w_i/m sum_p (1 + e_p . e_p+1)(E_p + E_p+1) ),
//  with
//    E_p = F_ip - F_i, e_p = E_p/|E_p|, and w_i = omega_angle (times rho(d_i) of eq. (10) with a
//    field).
//  - Volume-based, asymptotically uniform (Mikula et al. [11]): the potential psi solves
//    sum_j w_ij (psi_i - psi_j) = |V_i| (h.v_N)_i - (|V_i|/A) sum_k |V_k| (h.v_N)_k + omega_vol
//    (A/N_V - |V_i|) with psi fixed at vertex 0, and v_T,i = grad psi averaged over the co-volume
//    V_i: the integral of the piecewise-linear gradient over V_i divided by |V_i| (the paper's code
//    left out the division; perArea = false reproduces it).
#ifndef ShrinkWrap_TangentialRedistribution_h
#define ShrinkWrap_TangentialRedistribution_h

#include "Surface/SurfaceGeometry.h"

#include <Eigen/SparseCore>

namespace shrinkwrap
{

// weights: omega per vertex (omega_angle, times rho(d_i) where a field is given).
void angleVelocities(const SurfaceMesh& mesh, const std::vector<Vec3>& x, const SurfaceGeometry& g,
  const std::vector<double>& weights, std::vector<Vec3>& velocity);

struct VolumeRedistribution
{
  double omega = 1.0;
  bool perArea = true;
  double tolerance = 1e-10;
};

// normalVelocity: v_N per vertex (a vector). Returns false if the Poisson solve did not converge.
bool volumeVelocities(const SurfaceMesh& mesh, const std::vector<Vec3>& x, const SurfaceGeometry& g,
  const std::vector<Vec3>& normalVelocity, const VolumeRedistribution& settings,
  std::vector<double>& potential, std::vector<Vec3>& velocity);

} // namespace shrinkwrap

#endif
