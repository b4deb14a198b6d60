#include "Distance/PseudoNormals.h"
#include "Distance/SoupEdges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shrinkwrap
{

namespace
{
double angleAt(const Vec3& p, const Vec3& q, const Vec3& r)
{
  return angleBetween(q - p, r - p);
}

} // namespace

PseudoNormals::PseudoNormals(const TriangleSoup& soup)
{
  const std::size_t nt = soup.triangles.size();
  this->Face.resize(nt);
  std::vector<Vec3> vertex(soup.points.size(), Vec3::Zero());
  this->Corner.resize(nt);
  this->Edge.resize(nt);

  for (std::size_t t = 0; t < nt; ++t)
  {
    const auto& tri = soup.triangles[t];
    const Vec3 &a = soup.points[tri[0]], &b = soup.points[tri[1]], &c = soup.points[tri[2]];
    // Degenerate triangles have no normal and contribute nothing: a sliver's rounding-noise normal,
    // weighted by its corner of 180 degrees, would turn its neighbours' vertex pseudonormals.
    this->Face[t] = unitNormal(soup, static_cast<int>(t));
    if (!this->Face[t].isZero())
    {
      vertex[tri[0]] += angleAt(a, b, c) * this->Face[t];
      vertex[tri[1]] += angleAt(b, c, a) * this->Face[t];
      vertex[tri[2]] += angleAt(c, a, b) * this->Face[t];
    }
  }

  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Corner[t][k] = vertex[soup.triangles[t][k]];
    }
  }

  // Group the uses of each undirected edge; its pseudonormal is the sum of its faces' normals. An
  // edge of one triangle (a rim) or of more than two has no inside and outside, nor have its ends.
  this->Open.assign(nt, 0);
  std::vector<char> openVertex(soup.points.size(), 0);
  const EdgeUses uses = edgeUses(soup);
  forEachEdge(uses, [&](std::size_t first, std::size_t last) {
    Vec3 sum = Vec3::Zero();
    for (std::size_t k = first; k < last; ++k)
    {
      sum += this->Face[uses[k].triangle];
    }
    const std::size_t count = last - first;
    this->BoundaryEdges += count == 1;
    this->NonManifoldEdges += count > 2;
    for (std::size_t k = first; k < last; ++k)
    {
      this->Edge[uses[k].triangle][uses[k].slot] = sum;
      if (count != 2)
      {
        this->Open[uses[k].triangle] |= 1u << (static_cast<int>(Feature::Edge01) + uses[k].slot);
        openVertex[uses[first].key >> 32] = openVertex[uses[first].key & 0xffffffffu] = 1;
      }
    }
  });
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Open[t] |= openVertex[soup.triangles[t][k]] ? 1u << k : 0u;
    }
    this->Open[t] |= this->Face[t].isZero() ? 0x7fu : 0u;
  }
}

const Vec3& PseudoNormals::at(int triangle, Feature feature) const
{
  switch (feature)
  {
    case Feature::Face:
      return this->Face[triangle];
    case Feature::Edge01:
      return this->Edge[triangle][0];
    case Feature::Edge12:
      return this->Edge[triangle][1];
    case Feature::Edge20:
      return this->Edge[triangle][2];
    default:
      break;
  }
  return this->Corner[triangle][static_cast<int>(feature)]; // Vertex0..2 are 0..2
}

} // namespace shrinkwrap
