#include "Distance/ConfirmedSides.h"

#include "Common/Parallel.h"
#include "Surface/SelfIntersections.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace shrinkwrap
{

namespace
{
int rootOf(std::vector<int>& parent, int a)
{
  while (parent[a] != a)
  {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}

// The patch (a representative point) of every triangle that crosses none, -1 for those that do:
// triangles joined through shared points, crossing triangles left out.
std::vector<int> patchesOf(const TriangleSoup& soup, const std::vector<char>& crossing)
{
  const int nt = static_cast<int>(soup.triangles.size());
  std::vector<int> parent(soup.points.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int t = 0; t < nt; ++t)
  {
    if (!crossing[t])
    {
      const auto& tri = soup.triangles[t];
      const int root = rootOf(parent, tri[0]);
      parent[rootOf(parent, tri[1])] = root;
      parent[rootOf(parent, tri[2])] = root;
    }
  }
  std::vector<int> patch(nt, -1);
  for (int t = 0; t < nt; ++t)
  {
    patch[t] = crossing[t] ? -1 : rootOf(parent, soup.triangles[t][0]);
  }
  return patch;
}

// Samples spread over each patch in index order: every triangle of a small patch, eight of a larger
// one, and one in 32 of a large one (a patch joined to a buried part through a single point has
// parts of both; one in 32 finds any such part larger than that).
std::vector<int> samplesOf(const std::vector<int>& patch, std::size_t patchCount)
{
  const int nt = static_cast<int>(patch.size());
  std::vector<int> size(patchCount, 0), seen(patchCount, 0), samples;
  for (int p : patch)
  {
    size[p >= 0 ? p : 0] += p >= 0;
  }
  for (int t = 0; t < nt; ++t)
  {
    const int p = patch[t];
    if (p >= 0 && seen[p]++ % std::clamp(size[p] / 8, 1, 32) == 0)
    {
      samples.push_back(t);
    }
  }
  return samples;
}

// Per patch (indexed by its representative point), whether every sample sees the rest of the
// surface with winding number 1/2 +- 0.4; a loose far field is enough for that margin.
std::vector<char> patchesOk(
  const TriangleSoup& welded, const WindingNumber& winding, const std::vector<int>& patch)
{
  const std::vector<int> samples = samplesOf(patch, welded.points.size());
  std::vector<char> sampleOk(samples.size());
  parallelFor(0, static_cast<Index>(samples.size()), [&](Index b, Index e) {
    for (Index s = b; s < e; ++s)
    {
      const auto& tri = welded.triangles[samples[s]];
      const Vec3 c = (welded.points[tri[0]] + welded.points[tri[1]] + welded.points[tri[2]]) / 3.0;
      const double rest = winding.at(c, samples[s], 1.5);
      sampleOk[s] = rest > 0.1 && rest < 0.9;
    }
  });
  std::vector<char> ok(welded.points.size(), 1);
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    ok[patch[samples[s]]] &= sampleOk[s];
  }
  return ok;
}

// The crossing triangles among `candidates` (those of rejected patches), by their own grid.
std::vector<char> crossingAmong(const TriangleSoup& welded, const std::vector<char>& candidates)
{
  std::vector<std::array<int, 3>> subset;
  std::vector<int> original;
  for (std::size_t t = 0; t < candidates.size(); ++t)
  {
    if (candidates[t])
    {
      subset.push_back(welded.triangles[t]);
      original.push_back(static_cast<int>(t));
    }
  }
  const std::vector<char> found = findSelfIntersections(welded.points, subset).intersecting;
  std::vector<char> crossing(candidates.size(), 0);
  for (std::size_t k = 0; k < found.size(); ++k)
  {
    crossing[original[k]] = found[k];
  }
  return crossing;
}
} // namespace

// Patches are sampled first as they come (joined through shared points). A part inside another, or
// beyond a crossing, shows in the samples of its patch; crossing triangles are looked for only in
// the patches so rejected (the crossing check of every triangle cost a third of the winding sign on
// a mesh that is only open), left out, and what they joined is sampled again.
std::vector<char> confirmSides(const TriangleSoup& welded, const WindingNumber& winding)
{
  const int nt = static_cast<int>(welded.triangles.size());
  std::vector<int> patch = patchesOf(welded, std::vector<char>(nt, 0));
  std::vector<char> ok = patchesOk(welded, winding, patch);
  std::vector<char> rejected(nt, 0);
  bool anyRejected = false;
  for (int t = 0; t < nt; ++t)
  {
    rejected[t] = !ok[patch[t]];
    anyRejected = anyRejected || rejected[t];
  }
  if (anyRejected)
  {
    patch = patchesOf(welded, crossingAmong(welded, rejected));
    ok = patchesOk(welded, winding, patch);
  }
  std::vector<char> corner(welded.points.size(), 1);
  for (int t = 0; t < nt; ++t)
  {
    const bool good = patch[t] >= 0 && ok[patch[t]];
    for (int v : welded.triangles[t])
    {
      corner[v] = corner[v] && good;
    }
  }
  std::vector<char> confirmed(nt);
  for (int t = 0; t < nt; ++t)
  {
    const auto& tri = welded.triangles[t];
    confirmed[t] = corner[tri[0]] && corner[tri[1]] && corner[tri[2]];
  }
  return confirmed;
}

} // namespace shrinkwrap
