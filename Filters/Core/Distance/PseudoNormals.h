// Angle-weighted pseudonormals (Baerentzen & Aanaes, IEEE TVCG 2005): for a closed manifold mesh
// the sign of (x - p) . n(feature of p), with p the closest surface point to x, is the sign of x.
// That decides the band nodes, which the flood fill of Algorithm 1 (line 8) cannot reach.
#ifndef ShrinkWrap_PseudoNormals_h
#define ShrinkWrap_PseudoNormals_h

#include "Common/HugePages.h"
#include "Common/TriangleSoup.h"
#include "Distance/TriangleDistance.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shrinkwrap
{

class PseudoNormals
{
public:
  explicit PseudoNormals(const TriangleSoup& welded);

  const Vec3& at(int triangle, Feature feature) const;
  // Whether the pseudonormal there tells the sides apart: not on a rim or non-manifold edge, nor at
  // a corner of one, nor on a triangle without a normal.
  bool sure(int triangle, Feature feature) const
  {
    return !(this->Open[triangle] & (1u << static_cast<int>(feature)));
  }

  // Edges used by one triangle only (holes) and by more than two (non-manifold).
  long long boundaryEdges() const { return this->BoundaryEdges; }
  long long nonManifoldEdges() const { return this->NonManifoldEdges; }

private:
  // Megabytes for a large target: huge pages, whose first writes fault 2 MiB at a time.
  LargeVector<Vec3> Face;
  LargeVector<std::array<Vec3, 3>> Corner; // per triangle: its vertices' pseudonormals
  LargeVector<std::array<Vec3, 3>> Edge;   // per triangle: edges 01, 12, 20
  LargeVector<std::uint8_t> Open;          // per triangle: a bit per Feature that is not sure
  long long BoundaryEdges = 0;
  long long NonManifoldEdges = 0;
};

} // namespace shrinkwrap

#endif
