// A round of edits checked once (issue #10's speed). Edits rarely make the surface cross itself, and
// guarding each one (CrossingGuard) costs more than checking once what they made: the edits are made
// unguarded on a copy first, and the copy's new triangles are checked (the surface did not cross itself
// before). Where they cross, the edits are made again with only those near the crossings guarded (a
// second time also near the crossings the first redo made), and at last, if the surface still
// crosses, with every edit guarded. Where the last round needed guards, the next one starts with them.
#ifndef ShrinkWrap_CheckedEdits_h
#define ShrinkWrap_CheckedEdits_h

#include "Box.h"
#include "SelfIntersections.h"
#include "SurfaceMesh.h"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace shrinkwrap
{

// edit(mesh, guarded, only) edits mesh, guarding the edits within the boxes `only` (all of them when
// it is empty) if guarded, and tells whether it changed the connectivity. reach: how far around a
// crossing triangle the edits that may have made it lie. `remembered`: the boxes the last round of
// edits needed guarded, guarded from the first try (a crossing tends to come back where it was, step
// after step, and would cost a redo each time); on return the boxes this round needed, the newest
// kept up to kRememberedBoxes.
constexpr std::size_t kRememberedBoxes = 256;
template <typename Edit>
void editCheckedOnce(SurfaceMesh& mesh, double reach, std::vector<Box>& remembered, Edit&& edit)
{
  std::vector<Box> near = std::move(remembered);
  remembered.clear();
  for (int round = 0; round < 3; ++round)
  {
    SurfaceMesh trial = mesh;
    const bool changed = edit(trial, !near.empty(), near);
    const SelfIntersections found =
      changed ? findNewSelfIntersections(mesh, trial.points(), trial.triangles())
              : SelfIntersections{};
    if (found.pairs == 0)
    {
      mesh = std::move(trial);
      const std::size_t keep = std::min(near.size(), kRememberedBoxes);
      remembered.assign(near.end() - static_cast<std::ptrdiff_t>(keep), near.end());
      return;
    }
    const std::vector<Box> more = boxesAround(trial.points(), trial.triangles(), found, reach);
    near.insert(near.end(), more.begin(), more.end());
  }
  edit(mesh, true, {});
}

template <typename Edit>
void editCheckedOnce(SurfaceMesh& mesh, double reach, Edit&& edit) // a single round: nothing remembered
{
  std::vector<Box> none;
  editCheckedOnce(mesh, reach, none, edit);
}

} // namespace shrinkwrap

#endif
