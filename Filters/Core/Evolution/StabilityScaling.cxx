#include "Evolution/StabilityScaling.h"

#include "Surface/Icosphere.h"

#include <cmath>

namespace shrinkwrap
{

double meanCoVolume(double radius, long long vertexCount)
{
  return 4.0 * M_PI * radius * radius / static_cast<double>(vertexCount);
}

double meanCoVolume(double radius, int level)
{
  return meanCoVolume(radius, icosphereVertexCount(level));
}

double stabilityScale(double timeStep, double radius, long long vertexCount)
{
  return std::sqrt(timeStep / meanCoVolume(radius, vertexCount));
}

double stabilityScale(double timeStep, double radius, int level)
{
  return stabilityScale(timeStep, radius, icosphereVertexCount(level));
}

double stabilityScaleForEdgeLength(double timeStep, double edgeLength)
{
  return std::sqrt(timeStep / (0.5 * std::sqrt(3.0) * edgeLength * edgeLength));
}

} // namespace shrinkwrap
