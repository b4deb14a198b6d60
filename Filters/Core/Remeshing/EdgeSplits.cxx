#include "Remeshing/EdgeSplits.h"

namespace shrinkwrap
{

std::vector<std::array<int, 2>> edgesOf(const SurfaceMesh& mesh)
{
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    for (int p = mesh.ringBegin(i); p < mesh.ringEnd(i); ++p)
    {
      if (i < mesh.ring(p))
      {
        edges.push_back({ i, mesh.ring(p) });
      }
    }
  }
  return edges;
}

int splitEdges(SurfaceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
  const std::function<bool()>& stop)
{
  int splits = 0;
  StopPoll stopped(stop);
  for (std::size_t k = 0; k < edges.size() && !stopped(); ++k)
  {
    splits += mesh.split(edges[k][0], edges[k][1]) >= 0;
  }
  return splits > 0 && mesh.commit() ? splits : 0;
}

} // namespace shrinkwrap
