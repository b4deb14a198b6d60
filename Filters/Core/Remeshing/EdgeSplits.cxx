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

int splitEdges(SurfaceMesh& mesh, const std::vector<std::array<int, 2>>& edges)
{
  int splits = 0;
  for (const auto& e : edges)
  {
    splits += mesh.split(e[0], e[1]) >= 0;
  }
  return splits > 0 && mesh.commit() ? splits : 0;
}

} // namespace shrinkwrap
