// The geodesic icosphere of subdivision level s: the icosahedron, split 4-to-1 s times, every new
// vertex projected to the sphere. N_V = 10 * 4^s + 2 (12, 42, 162, 642, 2562, 10242, 40962), the
// closed form of the paper's recurrence (9) with N_V^0 = 12, N_E^0 = 30.
#ifndef ShrinkWrap_Icosphere_h
#define ShrinkWrap_Icosphere_h

#include "Common/TriangleSoup.h"

namespace shrinkwrap
{

TriangleSoup icosphere(int level, const Vec3& center = Vec3::Zero(), double radius = 1.0);

// Eq. (9) solved: expected vertex count after `level` 4-to-1 subdivisions of the icosahedron.
long long icosphereVertexCount(int level);

} // namespace shrinkwrap

#endif
