// A closed, 2-manifold triangle surface with its adjacency built once: for every vertex the one-ring
// of neighbours in counter-clockwise order (seen from outside) and the triangles between them, in
// compressed rows. Positions change every step of the evolution; the connectivity never does, so
// nothing is ever looked up by position.
#ifndef ShrinkWrap_SurfaceMesh_h
#define ShrinkWrap_SurfaceMesh_h

#include "Box.h"

#include <array>
#include <string>
#include <vector>

namespace shrinkwrap
{

class SurfaceMesh
{
public:
  // Checks that the triangles form a closed 2-manifold (every edge in exactly two triangles, with
  // opposite orientations; every vertex's triangles one fan; no unused vertex) and builds the rings.
  // Returns false with a message otherwise.
  static bool build(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles,
    SurfaceMesh& mesh, std::string& error);

  int vertexCount() const { return static_cast<int>(this->RingStart.size()) - 1; }
  int triangleCount() const { return static_cast<int>(this->Triangles.size()); }
  const std::vector<std::array<int, 3>>& triangles() const { return this->Triangles; }
  const std::vector<Vec3>& initialPoints() const { return this->InitialPoints; }

  // One-ring of vertex i: neighbours ring(p) for p in [ringBegin(i), ringEnd(i)), counter-clockwise.
  // The triangle (i, ring(p), ring(next(p))) is ringTriangle(p).
  int ringBegin(int i) const { return this->RingStart[i]; }
  int ringEnd(int i) const { return this->RingStart[i + 1]; }
  int ring(int p) const { return this->Ring[p]; }
  int ringTriangle(int p) const { return this->RingTriangle[p]; }
  int valence(int i) const { return this->RingStart[i + 1] - this->RingStart[i]; }
  // The entry after p in its vertex's ring, cyclically.
  int next(int i, int p) const { return p + 1 < this->RingStart[i + 1] ? p + 1 : this->RingStart[i]; }
  int previous(int i, int p) const { return p > this->RingStart[i] ? p - 1 : this->RingStart[i + 1] - 1; }
  // The entry of j in i's ring, or -1 when (i, j) is not an edge.
  int ringEntry(int i, int j) const
  {
    for (int p = this->RingStart[i]; p < this->RingStart[i + 1]; ++p)
    {
      if (this->Ring[p] == j)
      {
        return p;
      }
    }
    return -1;
  }

private:
  std::vector<std::array<int, 3>> Triangles;
  std::vector<Vec3> InitialPoints;
  std::vector<int> RingStart; // vertexCount + 1 offsets
  std::vector<int> Ring;
  std::vector<int> RingTriangle;
};

} // namespace shrinkwrap

#endif
