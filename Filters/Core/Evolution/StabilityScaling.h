// Scale for numerical stability (paper Section 2.4): the semi-implicit scheme is stable for
// tau ~ mu(V), the co-volume area. Areas scale with phi^2, so the factor that brings the mean
// co-volume of an icosphere of radius r and level s to tau is phi = sqrt(tau / mu_r(V)), with
// mu_r(V) = 4 pi r^2 / N_V^s (eqs. (8)-(9)). Eq. (7) prints a cube root, which is dimensionally
// wrong: it would make phi^2 mu_r = tau^(2/3) mu_r^(1/3), not tau.
#ifndef ShrinkWrap_StabilityScaling_h
#define ShrinkWrap_StabilityScaling_h

namespace shrinkwrap
{

// mu_r(V) of eq. (8) for a sphere of radius r with N_V vertices (an icosphere of level s has
// icosphereVertexCount(s), eq. (9)).
double meanCoVolume(double radius, long long vertexCount);
double meanCoVolume(double radius, int level);

// phi such that phi^2 mu_r(V) = tau.
double stabilityScale(double timeStep, double radius, long long vertexCount);
double stabilityScale(double timeStep, double radius, int level);
// The same for a surface remeshed towards edge length L: its co-volumes are near those of
// equilateral triangles, (sqrt(3) / 2) L^2 per vertex, whatever its vertex count (which follows the
// surface).
double stabilityScaleForEdgeLength(double timeStep, double edgeLength);

} // namespace shrinkwrap

#endif
