// A closed, 2-manifold triangle surface that can be edited: the positions of its vertices, further
// per-vertex data (velocities, say), and for every vertex the one-ring of neighbours in
// counter-clockwise order (seen from outside) with the triangles between them, in compressed rows
// that the evolver's loops read.
//
// Edits are local (split, flip, collapse, after pmp-library's SurfaceMesh) and keep a closed
// 2-manifold; positions and every vertex data follow them (a split interpolates, a collapse keeps
// the surviving vertex's). Edits see each other at once; the rings, the counts and the vertex
// numbering are those of the last commit() until the next one, which renumbers in order (dropping
// removed vertices and triangles) and rebuilds the rings. So a pass may decide its edits from the
// rings of the surface as it was, as long as no two of its edits touch the same triangle.
#ifndef ShrinkWrap_SurfaceMesh_h
#define ShrinkWrap_SurfaceMesh_h

#include "Common/Status.h"
#include "Common/Vec3.h"
#include "Surface/VertexProperties.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace shrinkwrap
{

class SurfaceMesh
{
public:
  // Checks that the triangles form a closed 2-manifold (every edge in exactly two triangles, with
  // opposite orientations; every vertex's triangles one fan; no unused vertex) and builds the
  // rings.
  static Status build(const std::vector<Vec3>& points,
    const std::vector<std::array<int, 3>>& triangles, SurfaceMesh& mesh);

  SurfaceMesh();
  SurfaceMesh(const SurfaceMesh& other);
  SurfaceMesh(SurfaceMesh&&) noexcept;
  SurfaceMesh& operator=(const SurfaceMesh& other);
  SurfaceMesh& operator=(SurfaceMesh&&) noexcept;
  ~SurfaceMesh();

  int vertexCount() const { return static_cast<int>(this->RingStart.size()) - 1; }
  int triangleCount() const { return static_cast<int>(this->Triangles.size()); }
  const std::vector<std::array<int, 3>>& triangles() const { return this->Triangles; }
  const std::vector<Vec3>& points() const { return this->Points; }
  std::vector<Vec3>& points() { return this->Points; }
  // Per-vertex data that follows edits (VertexProperties.h): the property `name`, made with `value`
  // at every vertex where it is new; the property if there is one of type T, else a false handle.
  template <typename T>
  VertexProperty<T> addVertexProperty(const std::string& name, const T& value)
  {
    return this->Properties.add<T>(name, this->Points.size(), value);
  }
  template <typename T>
  VertexProperty<T> vertexProperty(const std::string& name) const
  {
    return this->Properties.get<T>(name);
  }
  void removeVertexProperty(const std::string& name) { this->Properties.remove(name); }
  // A copy of the values of the property `name` of type T; empty if there is none.
  template <typename T>
  std::vector<T> vertexValues(const std::string& name) const
  {
    const VertexProperty<T> property = this->vertexProperty<T>(name);
    return property ? property.values() : std::vector<T>();
  }

  // One-ring of vertex i: neighbours ring(p) for p in [ringBegin(i), ringEnd(i)),
  // counter-clockwise. The triangle (i, ring(p), ring(next(p))) is ringTriangle(p).
  int ringBegin(int i) const { return this->RingStart[i]; }
  int ringEnd(int i) const { return this->RingStart[i + 1]; }
  int ring(int p) const { return this->Ring[p]; }
  int ringTriangle(int p) const { return this->RingTriangle[p]; }
  int valence(int i) const { return this->RingStart[i + 1] - this->RingStart[i]; }
  // The entry after p in its vertex's ring, cyclically.
  int next(int i, int p) const
  {
    return p + 1 < this->RingStart[i + 1] ? p + 1 : this->RingStart[i];
  }
  int previous(int i, int p) const
  {
    return p > this->RingStart[i] ? p - 1 : this->RingStart[i + 1] - 1;
  }
  // The entry of j in i's ring, or -1 when (i, j) is not an edge.
  int ringEntry(int i, int j) const;

  // Local edits. Each returns false (and changes nothing) where the edge does not exist or the edit
  // would not keep a closed 2-manifold.
  // Splits edge (a, b) at (1 - t) a + t b: a new vertex (returned, -1 if refused), numbered after
  // all others, with every vertex data interpolated alike; its two triangles become four.
  int split(int a, int b, double t = 0.5);
  // Replaces edge (a, b) of triangles (a, b, c) and (b, a, d) by (c, d): (a, d, c) and (d, b, c).
  bool flip(int a, int b);
  // Merges `gone` into `keep`, which moves to `position` and keeps its other data; the two
  // triangles on the edge disappear. The caller checks the link condition (only the two opposite
  // vertices are neighbours of both), which keeps the genus.
  bool collapse(int keep, int gone, const Vec3& position);
  // Removes the connected part of the surface that holds vertex v (as the rings of the last commit
  // join it; none of its triangles edited since), leaving a closed 2-manifold of the other parts;
  // returns its vertex count (0: v is not a vertex).
  int removePart(int v);
  bool edited() const { return this->Edits != nullptr; }
  // Renumbers and rebuilds the rings after edits; on failure (it should not happen: the edits keep
  // a manifold) the mesh is restored to the last commit.
  Status commit();

private:
  struct EditState;
  struct Renumbering // old index -> new, -1 where removed
  {
    std::vector<int> vertex, triangle;
  };
  Status connect(); // rings from Points and Triangles
  Renumbering compact(const std::vector<char>& removedVertex);
  Status reconnect(const std::vector<char>& touched, const Renumbering& renumbered); // after edits
  void beginEdit();
  int triangleOf(int a, int b) const; // the triangle with directed edge (a, b), or -1
  void setTriangle(int t, const std::array<int, 3>& triangle);

  std::vector<std::array<int, 3>> Triangles;
  std::vector<Vec3> Points;
  VertexProperties Properties;
  std::vector<int> RingStart; // vertexCount + 1 offsets
  std::vector<int> Ring;
  std::vector<int> RingTriangle;
  std::unique_ptr<EditState> Edits; // between the first edit and commit()
};

} // namespace shrinkwrap

#endif
