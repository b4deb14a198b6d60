#include "Wrap/FollowedFrames.h"

#include "Common/Parallel.h"
#include "Distance/DistanceSource.h"
#include "Surface/SelfIntersections.h"
#include "Wrap/TargetFeet.h"
#include "Wrap/Wrap.h"
#include "Wrap/WrapFields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace shrinkwrap
{

namespace
{
// The progress of a frame: its fields, then its start, then its steps.
constexpr double kFieldsShare = 0.4;
constexpr double kStartShare = 0.5;

// The unit normal of a triangle; zero when it is degenerate.
Vec3 unitNormal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 n = (b - a).cross(c - a);
  const double length = n.norm();
  return length > 0 ? Vec3(n / length) : Vec3(Vec3::Zero());
}

bool inside(const Box& domain, const std::vector<Vec3>& points)
{
  return std::all_of(
    points.begin(), points.end(), [&](const Vec3& p) { return domain.squaredDistance(p) == 0; });
}

// The largest ratio of an edge's length after the carry to before (or before to after).
double stretch(const SurfaceMesh& mesh, const std::vector<Vec3>& before)
{
  double most = 1;
  for (const auto& t : mesh.triangles())
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      const double now = (mesh.points()[a] - mesh.points()[b]).norm();
      const double was = (before[a] - before[b]).norm();
      most = std::max(most, std::max(now, was) / std::max(std::min(now, was), 1e-300));
    }
  }
  return most;
}

// How far the farthest vertex of the session's current surface lies from the target closed over
// its gaps (what the wrap lands on), in cells of the field.
double largestOff(const WrapSession& session)
{
  double most = 0;
  for (const Vec3& x : session.surface(session.computedSteps()).points)
  {
    most = std::max(most, std::abs(session.fields().driving.sample(x).value));
  }
  return most / session.plan().lattice.spacing.maxCoeff();
}

// Whether `points` lie on the target already (what the wrap lands on: `field`): 95% within
// follow.carriedCells cells of it.
bool onTarget(const std::vector<Vec3>& points, const TargetDistance& field, double cell,
  const FollowSettings& follow)
{
  if (points.empty())
  {
    return false;
  }
  std::vector<double> d(points.size());
  std::transform(points.begin(), points.end(), d.begin(),
    [&](const Vec3& x) { return std::abs(field.sample(x).value); });
  const auto rank = d.begin() + static_cast<std::ptrdiff_t>(0.95 * (d.size() - 1));
  std::nth_element(d.begin(), rank, d.end());
  return *rank <= follow.carriedCells * cell;
}

// Steps a carried start until it lands (FollowSettings); false when progress asked to stop. A
// failed step leaves the session's lastGood() set.
bool land(WrapSession& session, const FollowSettings& follow, const Progress& progress, int& steps)
{
  const int most = session.plan().settings.steps;
  double before = std::numeric_limits<double>::infinity(); // the largest off, a step before
  for (steps = 1; steps <= most; ++steps)
  {
    if (!session.advanceTo(steps, progress.stage(double(steps - 1) / most, double(steps) / most)))
    {
      return false;
    }
    if (session.lastGood() >= 0)
    {
      return true;
    }
    // Still on average, and landed everywhere or no nearer where it is farthest.
    const double off = largestOff(session);
    const std::optional<double> motion = session.meanMotion(steps);
    if (steps >= follow.minSteps && motion && *motion < follow.stillCells &&
      (off <= follow.landedCells || off > follow.stall * before))
    {
      return true;
    }
    before = off;
  }
  steps = most;
  return true;
}
} // namespace

bool carryWithTarget(const TriangleSoup& before, const TriangleSoup& after,
  std::vector<Vec3>& points, const TriangleSource* measured)
{
  if (before.points.size() != after.points.size() || before.triangles != after.triangles ||
    before.triangles.empty() || points.empty())
  {
    return false;
  }
  std::unique_ptr<const TriangleSource> own; // when the frame's own source was not kept
  if (!measured)
  {
    own = std::make_unique<const TriangleSource>(before);
    measured = own.get();
  }
  const auto nearestOn = [&](const Vec3& x) { // the triangle of `before` and the point on it
    const SourcePoint p = measured->closestPoint(x, std::numeric_limits<double>::infinity());
    return std::make_pair(p.found ? measured->inputTriangle(p.element) : -1, p.point);
  };
  const std::vector<Vec3> from = points;
  parallelFor(0, static_cast<Index>(points.size()), kQueryGrain, [&](Index b, Index e) {
    for (Index i = b; i < e; ++i)
    {
      const auto [triangle, point] = nearestOn(from[i]);
      if (triangle < 0)
      {
        continue;
      }
      const auto& t = before.triangles[triangle];
      const std::array<double, 3> w =
        barycentric(point, before.points[t[0]], before.points[t[1]], before.points[t[2]]);
      const Vec3 foot =
        w[0] * after.points[t[0]] + w[1] * after.points[t[1]] + w[2] * after.points[t[2]];
      const Vec3 n0 = unitNormal(before.points[t[0]], before.points[t[1]], before.points[t[2]]);
      const Vec3 n1 = unitNormal(after.points[t[0]], after.points[t[1]], after.points[t[2]]);
      const Vec3 offset = from[i] - point;
      const double along = offset.dot(n0); // the rest (off a rim or corner) keeps its direction
      points[i] = foot + along * n1 + (offset - along * n0);
    }
  });
  return true;
}

Status wrapFrame(const WrapTarget& target, const WrapPlan& plan, const FollowedWrap* previous,
  const FollowSettings& follow, const Contour& contour, const Progress& progress, Notes& notes,
  std::unique_ptr<WrapSession>& session, FrameReport& report)
{
  report = FrameReport();
  session.reset();
  notes.insert(notes.end(), plan.notes.begin(), plan.notes.end());
  WrapFields fields;
  if (Status made = makeWrapFields(target, plan, progress.stage(0, kFieldsShare), notes, fields);
      !made)
  {
    return made;
  }
  const Progress steps = progress.stage(kStartShare, 1);
  bool spent = false;
  if (previous)
  {
    SurfaceMesh start = previous->mesh;
    const std::vector<Vec3> before = start.points();
    const bool moved = previous->target && target.polygons &&
      carryWithTarget(
        *previous->target, *target.polygons, start.points(), previous->measured.get());
    if (moved) // where the carried surface would pass through itself, it stays
    {
      holdNewCrossings(before, start.points(), start.triangles());
    }
    // Landed as carried (on the target, its edges as they were): no step. Else onto this frame's
    // target (closed over its gaps) along its gradient first, where that does not make the
    // surface pass through itself.
    const double cell = plan.lattice.spacing.maxCoeff();
    const bool landed = stretch(start, before) <= follow.stretch &&
      onTarget(start.points(), fields.driving, cell, follow);
    const std::vector<Vec3> unprojected = start.points();
    for (int pass = 0; !landed && pass < follow.projections; ++pass)
    {
      parallelFor(0, static_cast<Index>(unprojected.size()), kQueryGrain, [&](Index b, Index e) {
        for (Index i = b; i < e; ++i)
        {
          Vec3& x = start.points()[i];
          const DistanceSample d = fields.driving.sample(x);
          x -= d.value * d.gradient;
        }
      });
    }
    if (!landed)
    {
      holdNewCrossings(unprojected, start.points(), start.triangles());
    }
    if (inside(fields.driving.grid().lattice().bounds(), start.points()))
    {
      std::unique_ptr<WrapSession> carried;
      spent = true; // a fresh start after this one makes its fields again (rare: no copy kept)
      if (WrapSession::create(std::move(fields), plan, start, carried))
      {
        carried->keepEvolver();
        report.steps = 0;
        if (!landed && !land(*carried, follow, steps, report.steps))
        {
          return Status::failure("aborted");
        }
        const double off = carried->lastGood() < 0 ? largestOff(*carried) : 0;
        if (carried->lastGood() < 0 && off <= follow.fitCells)
        {
          report.carried = true;
          session = std::move(carried);
          return {};
        }
        char why[200];
        std::snprintf(why, sizeof why,
          "the carried wrap lies up to %.3g cells off the target (parts came apart, or a hole "
          "opened)",
          off);
        report.fresh = carried->lastGood() >= 0 ? "the carried wrap failed: " + carried->failure()
                                                : std::string(why);
      }
      else
      {
        report.fresh = "the carried wrap cannot evolve";
      }
    }
    else
    {
      report.fresh = "the target moved out of the carried wrap's field";
    }
  }
  if (spent)
  {
    fields = WrapFields();
    if (Status made = makeWrapFields(target, plan, progress.stage(0, kFieldsShare), notes, fields);
        !made)
    {
      return made;
    }
  }
  const Status started = startSession(
    target, plan, std::move(fields), contour, progress.stage(kFieldsShare, kStartShare), session);
  if (!started)
  {
    return started;
  }
  session->keepEvolver();
  if (!session->advanceTo(plan.settings.steps, steps))
  {
    return Status::failure("aborted");
  }
  report.steps = session->shown(plan.settings.steps);
  return {};
}

FollowedWrap followedWrap(const WrapSession& session, int step,
  std::shared_ptr<const TriangleSoup> target, std::int64_t nextTrack)
{
  FollowedWrap followed;
  followed.target = std::move(target);
  followed.measured =
    std::dynamic_pointer_cast<const TriangleSource>(session.fields().target.exactShared());
  const WrapSession::Surface surface = session.surface(step);
  if (!SurfaceMesh::build(surface.points, *surface.cached->triangles, followed.mesh))
  {
    followed.nextTrack = nextTrack;
    return followed; // (the session's surfaces are closed 2-manifolds)
  }
  std::vector<TrackId> tracks;
  std::vector<Vec3> origins;
  if (!session.released() && session.evolver().mesh().vertexCount() == followed.mesh.vertexCount())
  {
    tracks = session.evolver().mesh().vertexValues<TrackId>(kTrackProperty);
    origins = session.evolver().mesh().vertexValues<Vec3>(kOriginProperty);
  }
  followed.displacement.assign(surface.points.size(), Vec3::Zero());
  for (std::size_t i = 0; i < origins.size() && i < surface.points.size(); ++i)
  {
    followed.displacement[i] = surface.points[i] - origins[i];
  }
  tracks.resize(surface.points.size());
  for (TrackId& track : tracks)
  {
    if (track.id < 0)
    {
      track.id = nextTrack++;
    }
  }
  followed.mesh.addVertexProperty<TrackId>(kTrackProperty, {}).values() = std::move(tracks);
  followed.mesh.addVertexProperty<Vec3>(kOriginProperty, Vec3::Zero()).values() = surface.points;
  followed.nextTrack = nextTrack;
  return followed;
}

bool FrameSchedule::follow(const std::vector<double>& times)
{
  if (times == this->Times)
  {
    return false;
  }
  this->Times = times;
  this->clear();
  return true;
}

int FrameSchedule::frameAt(double time) const
{
  const int last = static_cast<int>(this->Times.size()) - 1;
  if (std::isnan(time))
  {
    return last;
  }
  const auto after = std::upper_bound(this->Times.begin(), this->Times.end(), time);
  return std::clamp(static_cast<int>(after - this->Times.begin()) - 1, 0, std::max(last, 0));
}

int FrameSchedule::next(int wanted) const
{
  if (this->done(wanted))
  {
    return wanted;
  }
  return this->Newest >= 0 && this->Newest < wanted ? this->Newest + 1 : 0;
}

void FrameSchedule::markDone(int frame)
{
  if (frame != this->Newest + 1)
  {
    this->Done.clear();
  }
  this->Done.insert(frame);
  this->Newest = frame;
}

void FrameSchedule::clear()
{
  this->Done.clear();
  this->Newest = -1;
}

} // namespace shrinkwrap
