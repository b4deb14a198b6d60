#include "Wrap/LeftOut.h"

#include "Common/Box.h"
#include "Common/Parallel.h"
#include "Distance/AABBTree.h"
#include "Distance/WindingNumber.h"

#include <algorithm>
#include <numeric>

namespace shrinkwrap
{

namespace
{
struct Part
{
  int vertex = -1; // one of its corners: where the winding number is taken
  Box box;
};

int rootOf(std::vector<int>& up, int i)
{
  while (up[i] != i)
  {
    i = up[i] = up[up[i]];
  }
  return i;
}

std::vector<Part> partsOf(const TriangleSoup& soup)
{
  std::vector<int> up(soup.points.size());
  std::iota(up.begin(), up.end(), 0);
  for (const auto& t : soup.triangles)
  {
    up[rootOf(up, t[1])] = rootOf(up, t[0]);
    up[rootOf(up, t[2])] = rootOf(up, t[0]);
  }
  std::vector<int> partOfRoot(up.size(), -1);
  std::vector<Part> parts;
  for (const auto& t : soup.triangles)
  {
    int& part = partOfRoot[rootOf(up, t[0])];
    if (part < 0)
    {
      part = static_cast<int>(parts.size());
      parts.push_back({ t[0], Box() });
    }
    for (int c : t)
    {
      parts[part].box.extend(soup.points[c]);
    }
  }
  return parts;
}
} // namespace

LeftOutParts leftOutParts(const TriangleSoup& target, const TriangleSoup& wrap, double margin)
{
  const std::vector<Part> parts = partsOf(target);
  LeftOutParts result;
  result.parts = static_cast<long long>(parts.size());
  if (parts.size() < 2 || wrap.triangles.empty())
  {
    return result;
  }
  // A part is far when no point of the wrap lies within the margin of its box, nor so within the
  // ball about the box's centre that holds it.
  const AABBTree tree(wrap);
  std::vector<char> far(parts.size(), 0);
  parallelFor(0, static_cast<Index>(parts.size()), kQueryGrain, [&](Index b, Index e) {
    for (Index p = b; p < e; ++p)
    {
      const double reach = margin + 0.5 * parts[p].box.diagonal();
      far[p] = tree.closestPoint(parts[p].box.center(), reach * reach).triangle < 0;
    }
  });
  if (std::find(far.begin(), far.end(), 1) == far.end())
  {
    return result;
  }
  const WindingNumber winding(wrap, tree);
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    result.leftOut += far[p] && winding.at(target.points[parts[p].vertex]) < 0.5;
  }
  return result;
}

} // namespace shrinkwrap
