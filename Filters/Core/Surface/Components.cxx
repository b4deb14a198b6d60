#include "Surface/Components.h"

#include <algorithm>
#include <numeric>

namespace shrinkwrap
{

namespace
{
// Union-find over vertices joined by triangles; the root of each vertex's component.
std::vector<int> componentRoots(const TriangleSoup& surface)
{
  std::vector<int> parent(surface.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&parent](int v) {
    while (parent[v] != v)
    {
      v = parent[v] = parent[parent[v]];
    }
    return v;
  };
  for (const auto& t : surface.triangles)
  {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  for (size_t v = 0; v < parent.size(); ++v)
  {
    parent[v] = find(static_cast<int>(v));
  }
  return parent;
}

// Removes the components for which `drop(root)` holds; returns how many were removed.
template <typename Drop>
int removeComponents(TriangleSoup& surface, const std::vector<int>& root, Drop drop)
{
  int removed = 0;
  for (size_t v = 0; v < surface.points.size(); ++v)
  {
    removed += root[v] == static_cast<int>(v) && drop(root[v]);
  }
  if (removed == 0)
  {
    return 0;
  }
  // Keep the other components' triangles, with their vertices renumbered in order.
  std::vector<int> index(surface.points.size(), -1);
  TriangleSoup kept;
  for (size_t v = 0; v < surface.points.size(); ++v)
  {
    if (!drop(root[v]))
    {
      index[v] = static_cast<int>(kept.points.size());
      kept.points.push_back(surface.points[v]);
    }
  }
  for (const auto& t : surface.triangles)
  {
    if (index[t[0]] >= 0)
    {
      kept.triangles.push_back({ index[t[0]], index[t[1]], index[t[2]] });
    }
  }
  surface = std::move(kept);
  return removed;
}

} // namespace

int removeSpecks(TriangleSoup& surface, double size)
{
  const std::vector<int> root = componentRoots(surface);
  std::vector<Box> boxes(surface.points.size());
  for (size_t v = 0; v < surface.points.size(); ++v)
  {
    boxes[root[v]].extend(surface.points[v]);
  }
  return removeComponents(
    surface, root, [&](int r) { return (boxes[r].max - boxes[r].min).maxCoeff() < size; });
}

int removeCavities(TriangleSoup& surface)
{
  if (surface.points.empty())
  {
    return 0;
  }
  const std::vector<int> root = componentRoots(surface);
  std::vector<double> volume(surface.points.size(), 0.0);
  for (const auto& t : surface.triangles)
  {
    const Vec3& p = surface.points[t[0]];
    volume[root[t[0]]] += tripleProduct(p, surface.points[t[1]], surface.points[t[2]]) / 6;
  }
  // The largest piece is an outer one, whichever way the triangles face.
  const double outer = *std::max_element(
    volume.begin(), volume.end(), [](double u, double w) { return std::abs(u) < std::abs(w); });
  return removeComponents(surface, root, [&](int r) { return volume[r] * outer < 0; });
}

int handleCount(const TriangleSoup& surface)
{
  const std::vector<int> root = componentRoots(surface);
  std::vector<char> used(surface.points.size(), 0), isRoot(surface.points.size(), 0);
  for (const auto& t : surface.triangles)
  {
    for (int v : t)
    {
      used[v] = 1;
      isRoot[root[v]] = 1;
    }
  }
  const long long vertices = std::count(used.begin(), used.end(), 1);
  const long long components = std::count(isRoot.begin(), isRoot.end(), 1);
  const long long euler = vertices - static_cast<long long>(surface.triangles.size()) / 2;
  return static_cast<int>(components - euler / 2);
}

} // namespace shrinkwrap
