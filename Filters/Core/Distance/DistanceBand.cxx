#include "Distance/DistanceBand.h"
#include "Common/Parallel.h"

#include "Distance/TriangleBoxOverlap.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

namespace shrinkwrap
{

std::array<int, 6> nodeExtent(const GridLattice& lattice, const IndexList& nodes)
{
  std::array<int, 6> e = { lattice.dims[0], -1, lattice.dims[1], -1, lattice.dims[2], -1 };
  for (std::int64_t n : nodes)
  {
    const auto c = lattice.coordinates(n);
    for (int a = 0; a < 3; ++a)
    {
      e[2 * a] = std::min(e[2 * a], c[a]);
      e[2 * a + 1] = std::max(e[2 * a + 1], c[a]);
    }
  }
  return e;
}

IndexList bandNodes(const GridLattice& lattice, const IndexList& cells, int extraLayers,
  const std::array<bool, 6>& gridFaces, std::uint8_t* state)
{
  const std::int64_t sx = 1, sy = lattice.dims[0],
                     sz = static_cast<std::int64_t>(lattice.dims[0]) * lattice.dims[1];
  IndexList nodes;
  nodes.reserve(cells.size() * 3);
  auto add = [&](std::int64_t n) {
    if (state[n] == Unvisited)
    {
      state[n] = BandOnSurface;
      nodes.push_back(n);
    }
  };
  for (std::int64_t c : cells)
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      add(c + (corner & 1) * sx + ((corner >> 1) & 1) * sy + ((corner >> 2) & 1) * sz);
    }
  }
  for (int layer = 0; layer < extraLayers; ++layer)
  {
    const std::size_t end = nodes.size();
    for (std::size_t k = 0; k < end; ++k)
    {
      const std::int64_t n = nodes[k];
      const auto c = lattice.coordinates(n);
      if (c[0] > 0)
        add(n - sx);
      if (c[0] + 1 < lattice.dims[0])
        add(n + sx);
      if (c[1] > 0)
        add(n - sy);
      if (c[1] + 1 < lattice.dims[1])
        add(n + sy);
      if (c[2] > 0)
        add(n - sz);
      if (c[2] + 1 < lattice.dims[2])
        add(n + sz);
    }
  }
  const auto& d = lattice.dims;
  for (int face = 0; face < 6; ++face)
  {
    if (gridFaces[face])
    {
      std::array<int, 6> box = { 0, d[0] - 1, 0, d[1] - 1, 0, d[2] - 1 };
      const int axis = face / 2;
      box[2 * axis] = box[2 * axis + 1] = face % 2 ? d[axis] - 1 : 0;
      forEachFaceNode(lattice, box, add);
    }
  }
  return nodes;
}

bool computeBand(const DistanceSource& source, const GridLattice& lattice, IndexList nodes,
  double searchRadius, double onSurface, const Progress& progress, DistanceBand& band,
  std::uint8_t* state)
{
  const std::size_t n = nodes.size();
  band.nodes = std::move(nodes);
  band.closest.resize(n);
  band.distance.resize(n);
  band.sign.resize(n);
  band.normal.resize(n);
  band.element.resize(n);
  band.sure.resize(n);
  return forChunks(static_cast<long long>(n), 16, progress, [&](long long b, long long e) {
    for (long long k = b; k < e; ++k)
    {
      const std::int64_t node = band.nodes[k];
      const Vec3 x = lattice.position(lattice.coordinates(node));
      SourcePoint hit = source.closestPoint(x, searchRadius * searchRadius);
      if (!hit.found)
      {
        // a grid-boundary node of a grid that cuts the mesh
        hit = source.closestPoint(x, std::numeric_limits<double>::infinity());
      }
      band.closest[k] = hit.point;
      band.distance[k] = static_cast<float>(std::sqrt(hit.squaredDistance));
      const double side = hit.side;
      band.sign[k] = side < 0 ? -1 : 1;
      const Vec3 unit = hit.normal.normalized();
      band.normal[k] = { static_cast<float>(unit.x()), static_cast<float>(unit.y()),
        static_cast<float>(unit.z()) };
      band.element[k] = hit.element;
      band.sure[k] = hit.sure;
      state[node] =
        band.distance[k] <= onSurface ? BandOnSurface : (side < 0 ? BandInside : BandOutside);
    }
  });
}

} // namespace shrinkwrap
