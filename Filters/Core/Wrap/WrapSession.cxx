#include "Wrap/WrapSession.h"

#include "Common/Parallel.h"
#include "Evolution/StabilityScaling.h"

#include <algorithm>
#include <utility>

namespace shrinkwrap
{

Status WrapSession::create(WrapFields fields, const WrapPlan& plan, const SurfaceMesh& start,
  std::unique_ptr<WrapSession>& session)
{
  const Box domain = fields.driving.grid().lattice().bounds();
  for (const Vec3& p : start.points())
  {
    if (domain.squaredDistance(p) > 0)
    {
      return Status::failure(
        "the distance field does not contain the starting surface; enlarge the field "
        "(Offset Factor of Mesh Signed Distance) or start from a smaller surface");
    }
  }
  std::unique_ptr<WrapSession> s(new WrapSession());
  s->Plan = plan;
  s->Evolution = plan.evolution();
  s->Fields = std::move(fields);
  const Vec3 size = plan.targetBox.size();
  s->Radius = 0.5 * std::max(size.minCoeff(), 1e-3 * size.maxCoeff());
  s->Evolving = std::make_unique<Evolver>(start, s->Evolution, &s->Fields.driving, domain,
    s->scaleFor(start.vertexCount()), plan.targetBox.center());
  if (!s->Evolving->status())
  {
    return s->Evolving->status();
  }
  s->cacheCurrent(true);
  session = std::move(s);
  return {};
}

double WrapSession::scaleFor(int vertexCount) const
{
  const EvolverSettings& e = this->Evolution;
  if (!this->Plan.settings.automaticScaling)
  {
    return 1.0;
  }
  return e.remeshing
    ? stabilityScaleForEdgeLength(e.timeStep, e.remeshing->targetLength)
    : stabilityScale(e.timeStep, this->Radius, static_cast<long long>(vertexCount));
}

void WrapSession::cacheCurrent(bool connectivityChanged, bool edited)
{
  const Evolver& e = *this->Evolving;
  if (connectivityChanged || !this->EvolverTriangles)
  {
    this->EvolverTriangles =
      std::make_shared<const std::vector<std::array<int, 3>>>(e.mesh().triangles());
  }
  this->Cache.store(
    e.steps(), { e.state(), e.tangentialVelocity(), this->EvolverTriangles, e.scale(), edited });
}

bool WrapSession::advanceTo(int k, const Progress& progress)
{
  const int target = this->shown(k);
  if (this->Cache.has(target))
  {
    return true;
  }
  const auto& base = this->Cache.atOrBefore(target);
  Evolver& e = *this->Evolving;
  if (e.steps() != base.first || this->Stopped)
  {
    // Cached triangles were the evolver's own, so they always form a closed surface again.
    const bool reconnect = base.second.triangles != this->EvolverTriangles || this->Stopped;
    this->Stopped = false;
    if (e.restart(base.second.state, reconnect ? base.second.triangles.get() : nullptr, base.first,
          base.second.scale) &&
      reconnect)
    {
      this->EvolverTriangles = base.second.triangles;
    }
  }
  const int first = base.first;
  bool stopped = false;
  onAllCores([&] {
    for (int step = first + 1; step <= target; ++step)
    {
      // Within a step, progress stands at its middle: asked between its phases, it can stop it.
      const double within = (step - first - 0.5) / (target - first);
      e.setStop([&] { return !progress.report(within); });
      const StepReport report = e.step();
      e.setStop(nullptr);
      if (report.failure == Failure::Stopped)
      {
        this->Stopped = true; // the evolver's surface is no step's: the next run restarts it
        stopped = true;
        break;
      }
      ++this->Computed;
      if (!report.ok())
      {
        this->LastGood = step - 1;
        this->Failure = report.message;
        break;
      }
      this->cacheCurrent(report.connectivityChanged());
      if (!progress.report(static_cast<double>(step - first) / (target - first)))
      {
        stopped = true;
        break;
      }
    }
  });
  if (!stopped)
  {
    this->Cache.thin(this->Plan.settings.cacheMiB * 1024 * 1024, target);
  }
  return !stopped;
}

WrapSession::Surface WrapSession::surface(int k) const
{
  const auto& found = this->Cache.atOrBefore(this->shown(k));
  return { found.first, unscaled(found.second.state, found.second.scale, this->Evolving->center()),
    &found.second };
}

namespace
{
// The volume a closed surface encloses (signed by its orientation) and its area.
std::pair<double, double> volumeAndArea(
  const std::vector<Vec3>& x, const std::vector<std::array<int, 3>>& triangles)
{
  double volume = 0, area = 0;
  for (const auto& t : triangles)
  {
    volume += x[t[0]].dot(x[t[1]].cross(x[t[2]])) / 6;
    area += 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
  }
  return { volume, area };
}
} // namespace

std::optional<double> WrapSession::meanMotion(int k) const
{
  const Surface now = this->surface(k), before = this->surface(k - 1);
  const double cell = this->Plan.lattice.spacing.maxCoeff();
  if (k < 1 || now.step != k || before.step != k - 1 || !(cell > 0))
  {
    return std::nullopt;
  }
  const auto [v1, a1] = volumeAndArea(now.points, *now.cached->triangles);
  const auto [v0, a0] = volumeAndArea(before.points, *before.cached->triangles);
  if (!(a1 > 0))
  {
    return std::nullopt;
  }
  return std::abs(v1 - v0) / (a1 * cell);
}

Status WrapSession::edit(const std::function<void(SurfaceMesh&)>& change)
{
  Evolver& e = *this->Evolving;
  Status status = e.edit(change);
  e.setScale(this->scaleFor(e.mesh().vertexCount()));
  this->Cache.dropAfter(e.steps());
  this->LastGood = -1;
  this->Failure.clear();
  this->cacheCurrent(true, true);
  return status;
}

} // namespace shrinkwrap
