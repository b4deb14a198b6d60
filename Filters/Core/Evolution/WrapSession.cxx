#include "WrapSession.h"

#include "Parallel.h"
#include "StabilityScaling.h"

#include <cmath>

namespace shrinkwrap
{

Status WrapSettings::validate() const
{
  if (!(this->evolution.timeStep > 0) || !std::isfinite(this->evolution.timeStep))
    return Status::failure("TimeStep (tau) must be positive");
  if (this->start.subdivision < 0 || this->start.subdivision > 8)
    return Status::failure("SubdivisionLevel must be between 0 and 8");
  return {};
}

Status WrapSession::create(DistanceGrid field, const Box& targetBox, const SurfaceMesh& start,
  const WrapSettings& settings, std::unique_ptr<WrapSession>& session)
{
  const Box domain = field.lattice().bounds();
  for (const Vec3& p : start.points())
  {
    if (domain.squaredDistance(p) > 0)
    {
      return Status::failure("the distance field does not contain the starting surface; enlarge the field "
                             "(Offset Factor of Mesh Signed Distance) or start from a smaller surface");
    }
  }
  std::unique_ptr<WrapSession> s(new WrapSession());
  s->Settings = settings;
  s->Field = std::move(field);
  const Vec3 size = targetBox.size();
  s->Radius = 0.5 * std::max(size.minCoeff(), 1e-3 * size.maxCoeff());
  s->Evolution = std::make_unique<Evolver>(
    start, settings.evolution, &s->Field, domain, s->scaleFor(start.vertexCount()), targetBox.center());
  if (!s->Evolution->status())
  {
    return s->Evolution->status();
  }
  s->cacheCurrent(true);
  session = std::move(s);
  return {};
}

double WrapSession::scaleFor(int vertexCount) const
{
  return this->Settings.automaticScaling
    ? stabilityScale(this->Settings.evolution.timeStep, this->Radius, static_cast<long long>(vertexCount))
    : 1.0;
}

void WrapSession::cacheCurrent(bool connectivityChanged, bool edited)
{
  const Evolver& e = *this->Evolution;
  if (connectivityChanged || !this->EvolverTriangles)
  {
    this->EvolverTriangles = std::make_shared<const std::vector<std::array<int, 3>>>(e.mesh().triangles());
  }
  this->Cache.store(e.steps(), { e.state(), e.tangentialVelocity(), this->EvolverTriangles, e.scale(), edited });
}

bool WrapSession::advanceTo(int k, const Progress& progress)
{
  const int target = this->shown(k);
  if (this->Cache.has(target))
  {
    return true;
  }
  const auto& base = this->Cache.atOrBefore(target);
  Evolver& e = *this->Evolution;
  if (e.steps() != base.first)
  {
    // Cached triangles were the evolver's own, so they always form a closed surface again.
    const bool reconnect = base.second.triangles != this->EvolverTriangles;
    if (e.restart(base.second.state, reconnect ? base.second.triangles.get() : nullptr, base.first,
          base.second.scale) && reconnect)
    {
      this->EvolverTriangles = base.second.triangles;
    }
  }
  const int first = base.first;
  bool stopped = false;
  onAllCores([&] {
    for (int step = first + 1; step <= target; ++step)
    {
      const StepReport report = e.step();
      ++this->Computed;
      if (!report.ok())
      {
        this->LastGood = step - 1;
        this->Failure = report.message;
        break;
      }
      this->cacheCurrent(report.flips > 0 || report.collapses > 0);
      if (!progress.report(static_cast<double>(step - first) / (target - first)))
      {
        stopped = true;
        break;
      }
    }
  });
  if (!stopped)
  {
    this->Cache.thin(this->Settings.cacheMiB * 1024 * 1024, target);
  }
  return !stopped;
}

WrapSession::Surface WrapSession::surface(int k) const
{
  const auto& found = this->Cache.atOrBefore(this->shown(k));
  return { found.first, unscaled(found.second.state, found.second.scale, this->Evolution->center()),
    &found.second };
}

Status WrapSession::edit(const std::function<void(SurfaceMesh&)>& change)
{
  Evolver& e = *this->Evolution;
  Status status = e.edit(change);
  e.setScale(this->scaleFor(e.mesh().vertexCount()));
  this->Cache.dropAfter(e.steps());
  this->LastGood = -1;
  this->Failure.clear();
  this->cacheCurrent(true, true);
  return status;
}

} // namespace shrinkwrap
