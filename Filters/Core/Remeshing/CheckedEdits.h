// A round of edits checked once. Edits rarely make the surface cross itself, and
// guarding each one (CrossingGuard) costs more than checking once what they made: the edits are
// made unguarded on a copy first, and the copy's new triangles are checked (the surface did not
// cross itself before). Where they cross, the edits are made again with only those near the
// crossings guarded (a second time also near the crossings the first redo made), and at last, if
// the surface still crosses, with every edit guarded. Where recent rounds needed guards, the next
// one starts with them.
#ifndef ShrinkWrap_CheckedEdits_h
#define ShrinkWrap_CheckedEdits_h

#include "Common/Box.h"
#include "Surface/SelfIntersections.h"
#include "Surface/SurfaceMesh.h"

#include <functional>
#include <utility>
#include <vector>

namespace shrinkwrap
{

// edit(mesh, guarded, only) edits mesh, guarding the edits within the boxes `only` (all of them
// when it is empty) if guarded, and tells whether it changed the connectivity. reach: how far
// around a crossing triangle the edits that may have made it lie. `guardFirst`: boxes guarded from
// the first try (where recent rounds crossed: a crossing tends to come back where it was, step
// after step, and would cost a redo each time). Returns the boxes around the crossings this round
// found. `stop`, asked after each round, takes the round's edits unchecked and ends the rounds
// (a stopped step's result is discarded).
template <typename Edit>
std::vector<Box> editCheckedOnce(SurfaceMesh& mesh, double reach,
  const std::vector<Box>& guardFirst, Edit&& edit, const std::function<bool()>& stop = {})
{
  std::vector<Box> near = guardFirst, found;
  for (int round = 0; round < 3; ++round)
  {
    SurfaceMesh trial = mesh;
    const bool changed = edit(trial, !near.empty(), near);
    const SelfIntersections crossings = changed
      ? findNewSelfIntersections(mesh, trial.points(), trial.triangles(), stop)
      : SelfIntersections{};
    if (crossings.pairs == 0 || (stop && stop()))
    {
      mesh = std::move(trial);
      return found;
    }
    const std::vector<Box> more = boxesAround(trial.points(), trial.triangles(), crossings, reach);
    near.insert(near.end(), more.begin(), more.end());
    found.insert(found.end(), more.begin(), more.end());
  }
  edit(mesh, true, {});
  return found;
}

template <typename Edit>
void editCheckedOnce(
  SurfaceMesh& mesh, double reach, Edit&& edit, const std::function<bool()>& stop = {})
{
  editCheckedOnce(mesh, reach, {}, edit, stop);
}

} // namespace shrinkwrap

#endif
