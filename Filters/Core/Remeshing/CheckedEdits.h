// A round of edits checked once (issue #10's speed). Edits rarely make the surface cross itself, and
// guarding each one (CrossingGuard) costs more than checking once what they made: the edits are made
// unguarded on a copy first, and the copy's new triangles are checked (the surface did not cross itself
// before). Where they cross, the edits are made again with only those near the crossings guarded (a
// second time also near the crossings the first redo made), and at last, if the surface still
// crosses, with every edit guarded.
#ifndef ShrinkWrap_CheckedEdits_h
#define ShrinkWrap_CheckedEdits_h

#include "Box.h"
#include "SelfIntersections.h"
#include "SurfaceMesh.h"

#include <utility>
#include <vector>

namespace shrinkwrap
{

// edit(mesh, guarded, only) edits mesh, guarding the edits within the boxes `only` (all of them when
// it is empty) if guarded, and tells whether it changed the connectivity. reach: how far around a
// crossing triangle the edits that may have made it lie.
template <typename Edit>
void editCheckedOnce(SurfaceMesh& mesh, double reach, Edit&& edit)
{
  std::vector<Box> near;
  for (int round = 0; round < 3; ++round)
  {
    SurfaceMesh trial = mesh;
    const bool changed = edit(trial, round > 0, near);
    const SelfIntersections found =
      changed ? findNewSelfIntersections(mesh, trial.points(), trial.triangles())
              : SelfIntersections{};
    if (found.pairs == 0)
    {
      mesh = std::move(trial);
      return;
    }
    const std::vector<Box> more = boxesAround(trial.points(), trial.triangles(), found, reach);
    near.insert(near.end(), more.begin(), more.end());
  }
  edit(mesh, true, {});
}

} // namespace shrinkwrap

#endif
