// The whole of Shrink Wrap in the core, without a pipeline. A wrap runs in named phases:
//   target   makeTarget: the triangles checked, the points checked and measured
//   plan     planWrap (WrapPlan.h): every size chosen, the field placed
//   fields   the target's distance, closed over the gaps narrower than the Gap Size (WrapFields.h)
//   start    the starting surface: the offset surface of the closed target, an icosphere or a given
//   one session  the evolver on the fields (WrapSession.h), which then computes steps on request
// startWrap runs the last three from a plan; wrap() runs them all and the steps.
#ifndef ShrinkWrap_Wrap_h
#define ShrinkWrap_Wrap_h

#include "Common/Notes.h"
#include "Common/Progress.h"
#include "Common/Status.h"
#include "Common/TriangleSoup.h"
#include "Distance/ContourTopology.h"
#include "Distance/PointSource.h"
#include "Wrap/WrapPlan.h"
#include "Wrap/WrapSession.h"

#include <memory>

namespace shrinkwrap
{

// The target from its triangles and its points (either may be empty): the triangles checked
// (checkSoup), the points checked (checkPoints; alone, that they enclose something) and measured.
Status makeTarget(TriangleSoup polygons, PointList points, WrapTarget& target);

// The fields, the start and the session of a planned wrap. `contour` is marching cubes (for the
// offset start). Notes tell the user what the setup found (an unsigned field, specks left out).
Status startWrap(const WrapTarget& target, const WrapPlan& plan, const Contour& contour,
  const Progress& progress, Notes& notes, std::unique_ptr<WrapSession>& session);
// The start and the session on fields made for the plan (startWrap's second half).
Status startSession(const WrapTarget& target, const WrapPlan& plan, WrapFields fields,
  const Contour& contour, const Progress& progress, std::unique_ptr<WrapSession>& session);

// A wrap from its target to its last step.
struct WrapResult
{
  TriangleSoup surface; // the wrap, in the target's units
  WrapPlan plan;
  Notes notes;
  int steps = 0;       // the step shown: the last, or the last good one after a failure
  std::string failure; // why the evolution stopped early, if it did
};
Status wrap(const WrapTarget& target, const WrapSettings& settings, const Contour& contour,
  WrapResult& result, const Progress& progress = {});

} // namespace shrinkwrap

#endif
