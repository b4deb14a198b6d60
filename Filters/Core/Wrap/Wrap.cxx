#include "Wrap/Wrap.h"

#include "Distance/SignedDistance.h"
#include "Evolution/StartingSurface.h"

#include <string>

namespace shrinkwrap
{

namespace
{
// The shares of a setup's progress: the fields (distance and gap closing), then the start (its
// contour, coarsening and relaxation), which takes longer the finer the Target Edge Length.
constexpr double kFieldsShare = 0.5;

Status startOf(const WrapTarget& target, const WrapPlan& plan, const WrapFields& fields,
  const Contour& contour, const Progress& progress, SurfaceMesh& start)
{
  // The specks left out of the start are not the target's parts: what the wrap leaves out of the
  // target is measured on its last step (WrapSession::leftOut).
  int specks = 0;
  return startingSurface(fields.driving.grid(), plan.targetBox, target.start.get(), plan.start(),
    plan.settings.evolution.flips, contour, start, specks, progress);
}
} // namespace

Status makeTarget(TriangleSoup polygons, PointList points, WrapTarget& target)
{
  target = WrapTarget();
  if (!polygons.triangles.empty())
  {
    if (Status valid = checkSoup(polygons); !valid)
    {
      return valid;
    }
    target.polygons = std::make_shared<const TriangleSoup>(std::move(polygons));
  }
  if (!points.empty() || !target.polygons)
  {
    Status valid = checkPoints(points);
    if (valid && !target.polygons)
    {
      valid = checkPointsEnclose(points);
    }
    if (!valid)
    {
      return valid;
    }
    target.points = std::make_shared<const PointCloud>(measureCloud(std::move(points)));
  }
  return {};
}

Status startWrap(const WrapTarget& target, const WrapPlan& plan, const Contour& contour,
  const Progress& progress, Notes& notes, std::unique_ptr<WrapSession>& session)
{
  notes.insert(notes.end(), plan.notes.begin(), plan.notes.end());
  WrapFields fields;
  const Status made = makeWrapFields(target, plan, progress.stage(0, kFieldsShare), notes, fields);
  return made ? startSession(target, plan, std::move(fields), contour,
                  progress.stage(kFieldsShare, 1), session)
              : made;
}

Status startSession(const WrapTarget& target, const WrapPlan& plan, WrapFields fields,
  const Contour& contour, const Progress& progress, std::unique_ptr<WrapSession>& session)
{
  SurfaceMesh start;
  const Status started = startOf(target, plan, fields, contour, progress, start);
  return started ? WrapSession::create(std::move(fields), plan, start, session) : started;
}

Status wrap(const WrapTarget& target, const WrapSettings& settings, const Contour& contour,
  WrapResult& result, const Progress& progress)
{
  result = WrapResult();
  std::unique_ptr<WrapSession> session;
  Status status = planWrap(target, settings, result.plan);
  if (status)
  {
    status = startWrap(target, result.plan, contour, progress.stage(0, 0.3), result.notes, session);
  }
  if (!status)
  {
    return status;
  }
  if (!session->advanceTo(settings.steps, progress.stage(0.3, 1)))
  {
    return Status::failure("aborted");
  }
  const WrapSession::Surface surface = session->surface(settings.steps);
  result.surface = { surface.points, *surface.cached->triangles };
  result.steps = surface.step;
  result.failure = session->failure();
  return {};
}

} // namespace shrinkwrap
