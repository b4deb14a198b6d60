// The control functions of eq. (2), of the signed distance d at a vertex:
//   eps(d) = C1 (1 - exp(-d^2 / C2))                              diffusion, eq. (3) (C2 = 0: eps =
//   C1) eta(d) = C d ((-grad d . N) - D sqrt(1 - (grad d . N)^2))      advection, eq. (4) rho(d) =
//   A (1 - exp(-d^2))                                     redistribution weight, eq. (10)
#ifndef ShrinkWrap_ControlFunctions_h
#define ShrinkWrap_ControlFunctions_h

#include <algorithm>
#include <cmath>

namespace shrinkwrap
{

inline double diffusion(double d, double C1, double C2)
{
  return C2 > 0 ? C1 * (1.0 - std::exp(-d * d / C2)) : C1;
}

// alignment = grad d . N
inline double advection(double d, double alignment, double C, double D)
{
  return C * d * (-alignment - D * std::sqrt(std::max(0.0, 1.0 - alignment * alignment)));
}

inline double redistributionWeight(double d, double A)
{
  return A * (1.0 - std::exp(-d * d));
}

} // namespace shrinkwrap

#endif
