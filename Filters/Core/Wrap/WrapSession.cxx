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
  s->Center = plan.targetBox.center();
  s->Evolving = std::make_unique<Evolver>(
    start, s->Evolution, &s->Fields.driving, domain, s->scaleFor(start.vertexCount()), s->Center);
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
  this->LastLeftOut = {}; // the steps' addresses may be reused
  this->Samples.erase(e.steps());
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
    double sampled = 0; // bytes of the samples shown, within the cache's memory
    for (const auto& [step, samples] : this->Samples)
    {
      sampled += static_cast<double>(samples.size() * sizeof(DistanceSample));
    }
    this->Cache.thin(this->Plan.settings.cacheMiB * 1024 * 1024 - sampled, target);
    for (auto k = this->Samples.begin(); k != this->Samples.end();)
    {
      k = this->Cache.has(k->first) ? std::next(k) : this->Samples.erase(k);
    }
    this->releaseIfOver();
  }
  return !stopped;
}

void WrapSession::releaseIfOver()
{
  const int last = this->LastGood >= 0 ? this->LastGood : this->Plan.settings.steps;
  const TriangleSoup* target = this->targetTriangles();
  if (!target || this->Computed == 0 || this->KeepEvolver)
  {
    return;
  }
  std::size_t vertices = 0;
  for (int k = 0; k <= last; ++k)
  {
    if (!this->Cache.has(k))
    {
      return;
    }
    vertices += this->Cache.atOrBefore(k).second.state.size();
  }
  if (target->triangles.size() < vertices)
  {
    return; // measuring the samples would cost more than the target's memory is worth
  }
  for (int k = 0; k <= last; ++k)
  {
    this->targetSamples(this->surface(k));
  }
  this->leftOut(last);
  this->Evolving.reset();
  this->Fields = WrapFields();
}

const std::vector<DistanceSample>& WrapSession::targetSamples(const Surface& surface) const
{
  auto found = this->Samples.find(surface.step);
  if (found == this->Samples.end())
  {
    std::vector<DistanceSample> samples(surface.points.size());
    parallelFor(0, static_cast<Index>(samples.size()), [&](Index b, Index e) {
      for (Index i = b; i < e; ++i)
      {
        samples[i] = this->Fields.target.sample(surface.points[i]);
      }
    });
    found = this->Samples.emplace(surface.step, std::move(samples)).first;
  }
  return found->second;
}

WrapSession::Surface WrapSession::surface(int k) const
{
  const auto& found = this->Cache.atOrBefore(this->shown(k));
  return { found.first, unscaled(found.second.state, found.second.scale, this->Center),
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

const TriangleSoup* WrapSession::targetTriangles() const
{
  const DistanceSource* exact = this->Fields.target.exact();
  return exact ? exact->triangles() : nullptr;
}

LeftOutParts WrapSession::leftOut(int k) const
{
  Surface now = this->surface(k);
  if (now.cached == this->LastLeftOut.surface)
  {
    return this->LastLeftOut.parts; // measured (also before a release)
  }
  const TriangleSoup* target = this->targetTriangles();
  if (!target)
  {
    return {};
  }
  TriangleSoup wrap{ std::move(now.points), *now.cached->triangles };
  this->LastLeftOut = { now.cached,
    leftOutParts(*target, wrap, kLeftOutCells * this->Plan.lattice.spacing.maxCoeff()) };
  return this->LastLeftOut.parts;
}

Status WrapSession::edit(const std::function<void(SurfaceMesh&)>& change)
{
  if (this->released())
  {
    return Status::failure("the run is over: its evolver is released");
  }
  Evolver& e = *this->Evolving;
  Status status = e.edit(change);
  e.setScale(this->scaleFor(e.mesh().vertexCount()));
  this->Cache.dropAfter(e.steps());
  this->Samples.erase(this->Samples.upper_bound(e.steps()), this->Samples.end());
  this->LastGood = -1;
  this->Failure.clear();
  this->cacheCurrent(true, true);
  return status;
}

} // namespace shrinkwrap
