#include "Evolution/WrapSession.h"

#include "Evolution/GapClosing.h"
#include "Common/Parallel.h"
#include "Distance/PointSurface.h"
#include "Distance/UnionSource.h"
#include "Evolution/StabilityScaling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace shrinkwrap
{

namespace
{
// The width of the weights of a point set's fitted surface, in median neighbour distances: wide
// enough to average a few rings of neighbours, narrow enough that curvature biases the fit little.
constexpr double kFitWidthPerSpacing = 3;
// The automatic Gap Size of a point cloud, in median nearest-neighbour distances: the union of balls of
// half of it covers the random gaps of a uniform sample (its covering radius is about 3.5 of them for
// 4,000-200,000 points), so the wrap spans them and enters no hole the sampling left. Where the points
// are sparser in part (PointSpacing::sparse), in the spacing there.
constexpr double kPointGapPerNeighbourDistance = 8;
// ... and in cells of the field at least: a closing by a ball below a cell or so is lost in the grid's
// interpolation, and the wrap then meets sub-cell tunnels in it (handles the points do not have). 1.5
// rather than 2.5: at 200,000 points 8 spacings are below a cell, and 2.5 cells bridged the slot
// between the camel's legs and the dragon's handle; 1.5 kept them open and added no handle on the
// five clouds of the benchmark, clean or noisy (RESULTS.md, 2026-11-27).
constexpr double kMinPointGapCells = 1.5;
// ... and a dense cloud's field is made fine enough (up to 1.5 times Resolution) that the floor is
// at most 11 of them. At 200,000 points the floor at Resolution 80 spans 11-21 spacings and bridged
// the camel's tail to its legs and the dragon's claws (largest distances 1.57 and 1.62 times alpha
// wrap's); 1.06-1.5 times finer brought them within it. 10 spacings and up to twice finer gave the
// camel's clean points genus 4 (not 2), the noisy ones genus 3 (not 1): RESULTS.md, 2026-11-27 (night).
constexpr double kDensePointGapPerNeighbourDistance = 11;
constexpr double kMaxPointResolutionFactor = 1.5;
// ... and a sparser clean cloud's field fine enough (up to the same 1.5 times) that its spacing gap
// spans kSparsePointGapCells: a closing over fewer cells joins what lies a gap and a cell apart. At
// 20,000 points the camel's gap spans 1.77 cells at Resolution 80, and its legs stayed joined from the
// knees to the chest and from the hocks up; 1.41 times finer parted them. Not on a noisy cloud, whose
// noise blurs what a finer field would keep apart: the mech part's 200,000 noisy points took 1.5 times
// as long, and their largest distance rose to 1.59 times alpha wrap's (RESULTS.md, 2026-11-28, night).
constexpr double kSparsePointGapCells = 2.5;
// The automatic Target Edge Length of a point cloud, in median neighbour distances: a triangle then
// spans a few dozen points, the detail their fitted surface holds; never coarser than a mesh's
// automatic length (diagonal / kLengthDivisor) unless noisy (below), nor finer than diagonal /
// kMaxPointLengthDivisor.
// Measured on CGAL meshes sampled with 20,000 and 200,000 points (RESULTS.md): diagonal / 50 and about
// diagonal / 100.
constexpr double kPointEdgePerNeighbourDistance = 10;
constexpr double kMaxPointLengthDivisor = 200;
// ... and on a noisy cloud up to kEdgePerNoise times its noise (PointSurface::typicalNoise), at most
// diagonal / kNoisyPointLengthDivisor: its fitted surface holds no detail the noise has not blurred,
// and finer triangles only cost time. At 20,000 points with noise of 0.25% of the diagonal (measured
// 0.22-0.30%; clean CGAL clouds 0.005-0.07%, below diagonal / 50 / 16), diagonal / 50 took 1.0-1.9
// times alpha wrap's time at diag/50, diagonal / 30 0.69-1.00 times, with means at most 0.74 times
// and largest distances 1.29 times alpha wrap's (RESULTS.md, 2026-11-28, evening). At 200,000 noisy
// points 10 spacings (diagonal / 61 to / 45) decide.
constexpr double kEdgePerNoise = 16;
constexpr double kNoisyPointLengthDivisor = 30;
// The offset start's farthest distance from the closed target, in Gap Sizes. Beyond half the gap the
// start merges parts the closing keeps apart (handles the target has not, as between knot1's strands);
// at half the gap a slot the closing just keeps open (as wide as the gap) touches itself in the start,
// and the grid's interpolation decides. 0.4 leaves a fifth of the gap between the two: at 20,000
// points the hand lost one of its two handles and the armadillo's largest distance fell 2.52% ->
// 2.17%; the meshes and the 200,000-point clouds, whose start lies 3 cells or 1 cell out, wrap as
// before (RESULTS.md, 2026-11-27). Below 0.4 the start nears the contour's sub-cell handles (0.3: the
// mech part's 20,000 points wrapped at genus 5, not 3).
constexpr double kMaxStartOffsetPerGap = 0.4;
} // namespace

Status WrapSettings::validate() const
{
  if (!(this->evolution.timeStep > 0) || !std::isfinite(this->evolution.timeStep))
    return Status::failure("TimeStep (tau) must be positive");
  if (this->start.subdivision < 0 || this->start.subdivision > 8)
    return Status::failure("SubdivisionLevel must be between 0 and 8");
  if (!(this->targetLength >= 0) || !std::isfinite(this->targetLength))
    return Status::failure("TargetEdgeLength must not be negative (0: automatic)");
  if (!(this->gapSize >= 0) || !std::isfinite(this->gapSize))
    return Status::failure("GapSize must not be negative (0: automatic)");
  if (!(this->edgeRange[0] >= kShortestEdge && this->edgeRange[0] <= 1 && this->edgeRange[1] >= 1 &&
        this->edgeRange[1] <= kLongestEdge))
    return Status::failure("EdgeLengthRange must hold 1: from 0.1 to 1, then from 1 to 4 (times the Target Edge Length)");
  if (!(this->evolution.rims.creaseAngle >= 0 && this->evolution.rims.creaseAngle <= 180))
    return Status::failure("CreaseAngle must be between 0 and 180 degrees");
  return {};
}

Status WrapSettings::fits(const Box& targetBox) const
{
  if (!this->remeshing || !(this->targetLength > 0))
  {
    return {};
  }
  // Equilateral triangles of edge L over the target box's surface (more than the wrap's): vertices
  // about 2 A / (sqrt(3) L^2).
  // The shortest adaptive edges bound it.
  const double shortest = this->edgeRange[0] * this->targetLength;
  const double vertices = 2 * 2 * targetBox.halfArea() / (std::sqrt(3.0) * shortest * shortest);
  if (!(vertices <= kMaxVertices))
  {
    std::ostringstream message;
    message << "TargetEdgeLength " << this->targetLength << " would make about " << vertices
            << " vertices on this target (at most " << kMaxVertices << "); raise it";
    return Status::failure(message.str());
  }
  return {};
}

WrapSettings WrapSettings::resolved(const Box& targetBox) const
{
  WrapSettings s = *this;
  const double diagonal = targetBox.diagonal();
  if (s.targetLength <= 0)
  {
    s.targetLength = diagonal / kLengthDivisor;
  }
  if (s.gapSize <= 0)
  {
    s.gapSize = diagonal / kGapDivisor;
  }
  s.evolution.remeshing.targetLength = s.remeshing ? s.targetLength : 0;
  s.start.coarsenTo = s.evolution.remeshing.targetLength;
  s.evolution.remeshing.shortest = s.edgeRange[0];
  s.evolution.remeshing.longest = s.edgeRange[1];
  s.evolution.remeshing.chordError = kChordError;
  s.start.maxOffset = kMaxStartOffsetPerGap * s.gapSize;
  return s;
}

GridPlacement WrapSettings::fieldPlacement(const Box& targetBox, bool givenStart) const
{
  GridPlacement placement;
  placement.resolution = this->resolution;
  placement.offsetFactor = kPaperOffsetFactor;
  // Beyond the box scaled by placement.boxScale, o s on every side (s its longest side) must hold the
  // start's offset, the closing's radius and three cells of room: o s >= (offset + 3) h + gap / 2, with
  // h = s (1 + 2 o) / resolution.
  const double side = placement.boxScale * targetBox.size().maxCoeff();
  const double cells = (this->start.offset + 3) / std::max(this->resolution, 1);
  const double room = 1 - 2 * cells;
  if (!givenStart && this->start.shape == StartShape::OffsetSurface && side > 0 && room > 0)
  {
    placement.offsetFactor = std::min((cells + 0.5 * this->gapSize / side) / room, kPaperOffsetFactor);
  }
  return placement;
}

Status wrapFields(DistanceGrid grid, bool isSigned, std::shared_ptr<const DistanceSource> exact,
  const WrapSettings& settings, WrapFields& fields)
{
  DistanceGrid closed;
  if (Status status = closingField(grid, 0.5 * settings.gapSize, exact.get(), false, closed); !status)
  {
    return status;
  }
  if (!settings.exactNearTarget)
  {
    exact.reset();
  }
  fields.driving = TargetDistance(std::move(closed), exact, settings.exactBand, isSigned);
  fields.target = TargetDistance(std::move(grid), exact, settings.exactBand, isSigned);
  return {};
}

Status checkPointsEnclose(const PointList& points)
{
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points)
  {
    mean += p;
  }
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points)
  {
    covariance += (p - mean) * (p - mean).transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariance);
  // Extents along the principal axes (ascending eigenvalues: the thinnest first).
  std::array<double, 3> extent{};
  for (int a = 0; a < 3; ++a)
  {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Vec3& p : points)
    {
      const double t = (p - mean).dot(axes.eigenvectors().col(a));
      low = std::min(low, t);
      high = std::max(high, t);
    }
    extent[a] = high - low;
  }
  const double tolerance = 1e-6 * extent[2];
  if (!(extent[2] > 0))
    return Status::failure("all the points coincide, so they enclose nothing to wrap");
  if (extent[1] <= tolerance)
    return Status::failure("the points lie on a line, so they enclose nothing to wrap (Mesh Signed Distance "
                           "measures the distance to them)");
  if (extent[0] <= tolerance)
    return Status::failure("the points lie in a plane, so they enclose nothing to wrap (Mesh Signed Distance "
                           "measures the distance to them)");
  return {};
}

double PointCloud::noise() const
{
  return this->surface ? this->surface->typicalNoise() : 0.0;
}

PointCloud measureCloud(PointList points)
{
  PointCloud cloud;
  cloud.points = std::make_shared<const PointSource>(std::move(points));
  const PointSpacing spacing = cloud.points->spacing();
  cloud.spacing = spacing.median;
  cloud.sparseSpacing = spacing.sparse;
  if (cloud.spacing > 0)
  {
    cloud.surface = std::make_shared<const PointSurface>(cloud.points, kFitWidthPerSpacing * cloud.spacing);
  }
  return cloud;
}

WrapSettings withPointSizes(WrapSettings settings, const Box& box, const PointCloud& cloud, bool givenStart)
{
  const double spacing = cloud.spacing;
  const double diagonal = box.diagonal();
  // Noise above what an edge of the mesh's automatic length (diagonal / kLengthDivisor) would show.
  const bool noisy = kEdgePerNoise * cloud.noise() > diagonal / WrapSettings::kLengthDivisor;
  if (settings.targetLength <= 0 && spacing > 0)
  {
    const double coarsest = std::clamp(
      kEdgePerNoise * cloud.noise(), diagonal / WrapSettings::kLengthDivisor, diagonal / kNoisyPointLengthDivisor);
    settings.targetLength =
      std::clamp(kPointEdgePerNeighbourDistance * spacing, diagonal / kMaxPointLengthDivisor, coarsest);
  }
  if (settings.gapSize > 0)
  {
    return settings;
  }
  const double spacingGap = kPointGapPerNeighbourDistance * std::max(spacing, cloud.sparseSpacing);
  settings.gapSize = spacingGap;
  // A dense cloud's spacing gap lies under the grid's floor: a finer field lowers the floor. A sparser
  // clean one's may span too few cells for the closing: a finer field resolves it.
  if (GridLattice lattice; placeGrid(box, settings.resolved(box).fieldPlacement(box, givenStart), lattice))
  {
    const double cell = lattice.spacing.maxCoeff();
    const double dense = kMinPointGapCells * cell / (kDensePointGapPerNeighbourDistance * spacing);
    const bool sparse = !noisy && spacingGap >= kMinPointGapCells * cell;
    const double finer = std::max(dense, sparse ? kSparsePointGapCells * cell / spacingGap : 0.0);
    if (finer > 1)
    {
      const double resolution = std::ceil(std::min(finer, kMaxPointResolutionFactor) * settings.resolution);
      settings.resolution = static_cast<int>(std::min(resolution, double(std::numeric_limits<int>::max())));
    }
  }
  // The cell depends on the gap (the box holds the closing): twice round settles it.
  for (int pass = 0; pass < 2; ++pass)
  {
    GridLattice lattice;
    if (!placeGrid(box, settings.resolved(box).fieldPlacement(box, givenStart), lattice))
    {
      break;
    }
    settings.gapSize = std::max(spacingGap, kMinPointGapCells * lattice.spacing.maxCoeff());
  }
  return settings;
}

Status pointWrapFields(DistanceGrid grid, const PointCloud& cloud, const WrapSettings& settings, WrapFields& fields,
  std::shared_ptr<const DistanceSource> polygons)
{
  // The grid is the distance to the points and the polygons: the closing's sites come from the nearer.
  std::shared_ptr<const DistanceSource> nearest = cloud.points;
  if (polygons)
  {
    nearest = std::make_shared<const UnionSource>(std::vector<std::shared_ptr<const DistanceSource>>{ polygons, cloud.points });
  }
  // Cavities filled: the union of balls around points that sample a sheet is a shell.
  DistanceGrid closed;
  if (Status status = closingField(grid, 0.5 * settings.gapSize, nearest.get(), true, closed); !status)
  {
    return status;
  }
  // The near field of the driving distance: the points' fitted surface, not the nearest point (which
  // would pull the closing's membranes between the points into dimples).
  std::shared_ptr<const DistanceSource> surface = cloud.surface;
  if (polygons)
  {
    surface = surface ? std::make_shared<const UnionSource>(std::vector<std::shared_ptr<const DistanceSource>>{ polygons, surface })
                      : polygons;
  }
  fields.driving = TargetDistance(std::move(closed), settings.exactNearTarget ? surface : nullptr, settings.exactBand, true);
  // The wrap lies within half the gap of a point (inside the union of balls the closing erodes): a band
  // that wide makes the Distance array exact at every vertex.
  const double cell = grid.lattice().spacing.maxCoeff();
  const double band = std::max(settings.exactBand, 0.5 * settings.gapSize / cell + 1);
  fields.target = TargetDistance(std::move(grid), settings.exactNearTarget ? nearest : nullptr, band, false);
  return {};
}

Status WrapSession::create(WrapFields fields, const Box& targetBox, const SurfaceMesh& start,
  const WrapSettings& settings, std::unique_ptr<WrapSession>& session)
{
  const Box domain = fields.driving.grid().lattice().bounds();
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
  s->Fields = std::move(fields);
  const Vec3 size = targetBox.size();
  s->Radius = 0.5 * std::max(size.minCoeff(), 1e-3 * size.maxCoeff());
  s->Evolution = std::make_unique<Evolver>(
    start, settings.evolution, &s->Fields.driving, domain, s->scaleFor(start.vertexCount()), targetBox.center());
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
  const EvolverSettings& e = this->Settings.evolution;
  if (!this->Settings.automaticScaling)
  {
    return 1.0;
  }
  return e.remeshing.targetLength > 0 ? stabilityScaleForEdgeLength(e.timeStep, e.remeshing.targetLength)
                                      : stabilityScale(e.timeStep, this->Radius, static_cast<long long>(vertexCount));
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
