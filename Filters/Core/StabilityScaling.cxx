#include "StabilityScaling.h"

#include "Icosphere.h"

#include <cmath>

namespace shrinkwrap
{

double meanCoVolume(double radius, int level)
{
  return 4.0 * M_PI * radius * radius / static_cast<double>(icosphereVertexCount(level));
}

double stabilityScale(double timeStep, double radius, int level)
{
  return std::sqrt(timeStep / meanCoVolume(radius, level));
}

} // namespace shrinkwrap
