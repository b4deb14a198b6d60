#include "Distance/PointSurface.h"

#include "Common/Parallel.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>

namespace shrinkwrap
{

namespace
{
constexpr double kCutoff = 2.5;  // neighbours within this many widths (weights below 0.002 beyond)
constexpr double kMinWeight = 1; // a fit needs the weight of at least one point at the centre
// In widths, the points' centroid beside the foot (along the plane, closestPoint): up to half of
// this the fit is trusted fully, beyond this not at all (a one-sided fit). Sampling holes of a
// random sample (up to about 3.5 neighbour distances, more than h) need the full trust; a fit
// beyond a gap's rim does not.
constexpr double kMaxOffCentre = 1.0;
// In widths, a point's lean (its neighbours' centroid off it, along the plane): up to kEvenLean the
// noise of an even random sample, from kRimLean on the lean of a point on a straight rim (1 /
// sqrt(pi)).
constexpr double kEvenLean = 0.3;
constexpr double kRimLean = 0.5;
// In widths: a patch speaks for feet within this of its centre; further, one centred on the foot
// does. A surface point's nearest sample of a uniform random cloud lies beyond r with probability
// exp(-pi rho r^2): beyond three quarters of a width (2.25 median spacings) for one in thirty;
// within that the quadric, fitted over 2.5 widths, holds.
constexpr double kNearAnchor = 0.75;
// A rim leaves half the directions around a centre empty; a random sample's sampling hole leaves
// far less (its points lie all around, only nearer on one side).
constexpr double kMaxAngularGap = 2 * M_PI / 3;
// In widths: how far along a rim the search for its points reaches from each one found (a jagged
// rim's points lie up to a few widths apart).
constexpr double kRimReach = 3;
// In widths (of the finest scale at which the points around a rim point look flat): the largest RMS
// height of the points over its plane: clean points lie within a few hundredths of it, noisy ones
// (at the width where their plane shows) within about a sixth; above, the point is no rim's.
constexpr double kMaxRimSpread = 0.2;
// One point in 4^kTypicalSample tells the width at which most of a cloud's points look flat.
constexpr int kTypicalSample = 4;
constexpr double kMaxFlatness = 0.25; // smallest over middle eigenvalue: above it, no plane
constexpr double kMinPivot = 1e-6;    // of the quadric's normal equations, relative to the largest
constexpr double kMaxLift = 0.2; // in widths: the most a quadric may move the plane's surface point
// Where no plane fits on a cloud whose noise hides the plane at h (firstLayer): the points within
// kLayerRadius widths of the line of sight, and of those the ones within kLayerDepth noises of the
// shallowest (a Gaussian's outermost of some dozens lies about 2 sigma out, so the window takes the
// near sheet's band whole and a far sheet only where the part is thinner than about 2 sigma), at
// least kMinLayerPoints of them.
constexpr double kLayerRadius = 0.5;
constexpr double kLayerDepth = 4;
constexpr int kMinLayerPoints = 5;

// The axes of a plane's (u, v) coordinates, the same for every use of one patch.
std::array<Vec3, 2> tangents(const Vec3& normal)
{
  const Vec3 t1 = normal.unitOrthogonal();
  return { t1, normal.cross(t1) };
}

// Whether point i is in the sample of scale s: one point in 4^s, picked by a hash of its index (not
// by stride: a scanner's order has rows).
bool inSample(std::size_t i, int s)
{
  const std::uint64_t mask = (std::uint64_t(1) << (2 * s)) - 1;
  return (((i + 1) * 0x9E3779B97F4A7C15ull) >> 40 & mask) == 0;
}

// A patch's centroid off its centre, along its plane: how far its points lean to one side.
Vec3 leanInPlane(const Vec3& centroid, const Vec3& centre, const Vec3& normal)
{
  const Vec3 lean = centroid - centre;
  return lean - lean.dot(normal) * normal;
}
} // namespace

PointSurface::Scale::Scale(const PointList& sample, double w)
  : width(w)
  , grid(sample, kCutoff * w)
{
}

PointSurface::PointSurface(std::shared_ptr<const PointSource> points, double width)
  : Points(std::move(points))
{
  const PointList& all = this->Points->points();
  this->Scales.resize(kScales);
  parallelFor(0, kScales, 1, [&](Index b, Index e) {
    for (Index s = b; s < e; ++s)
    {
      if (s == 0) // every point: binned from the source's own (a copy is fresh memory, and slow)
      {
        this->Scales[s] = std::make_unique<const Scale>(all, width);
        continue;
      }
      PointList sample;
      sample.reserve(all.size() >> (2 * s));
      for (std::size_t i = 0; i < all.size(); ++i)
      {
        if (inSample(i, static_cast<int>(s)))
        {
          sample.push_back(all[i]);
        }
      }
      this->Scales[s] = std::make_unique<const Scale>(sample, width * (1 << s));
    }
  });
  this->Slots = LargeVector<std::atomic<std::uint32_t>>(all.size());
  this->Chunks = std::vector<std::atomic<Chunk*>>(all.size() / Chunk::kSize + 1);
  this->measureTypical();
}

PointSurface::~PointSurface()
{
  for (auto& chunk : this->Chunks)
  {
    delete chunk.load();
  }
}

void PointSurface::gather(const Vec3& centre, const Scale& scale, Neighbourhood& around) const
{
  around.centre = centre;
  around.offsets.clear();
  around.weights.clear();
  const double inverse = 1 / (scale.width * scale.width);
  scale.grid.forEachWithin(centre, kCutoff * scale.width, [&](int, const Vec3& point) {
    const Vec3 d = point - centre;
    around.offsets.push_back(d);
    around.weights.push_back(std::exp(-d.squaredNorm() * inverse));
  });
}

bool PointSurface::fit(const Neighbourhood& around, Plane& plane)
{
  double total = 0;
  Vec3 sum = Vec3::Zero();
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < around.offsets.size(); ++i)
  {
    const Vec3& d = around.offsets[i];
    const double w = around.weights[i];
    total += w;
    sum += w * d;
    moments += w * d * d.transpose();
  }
  const Vec3 mean = total > 0 ? Vec3(sum / total) : Vec3::Zero();
  plane.centroid = around.centre + mean;
  if (!(total >= kMinWeight))
  {
    return false;
  }
  const Eigen::Matrix3d covariance = moments / total - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes;
  axes.computeDirect(covariance);
  const Eigen::Vector3d& lambda = axes.eigenvalues(); // ascending
  if (!(lambda[0] <= kMaxFlatness * lambda[1]))
  {
    return false;
  }
  plane.normal = axes.eigenvectors().col(0).normalized();
  return true;
}

void PointSurface::fitQuadric(const Neighbourhood& around, Patch& patch)
{
  // Heights over the plane, in widths, fitted by w = a0 + a1 u + a2 v + a3 u^2 + a4 u v + a5 v^2
  // about the centroid (u = v = 0).
  Eigen::Matrix<double, 6, 6> normalMatrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  const double scale = 1 / patch.width;
  const Vec3 shift = around.centre - patch.plane.centroid;
  const auto [t1, t2] = tangents(patch.plane.normal);
  for (std::size_t i = 0; i < around.offsets.size(); ++i)
  {
    const Vec3 d = (around.offsets[i] + shift) * scale;
    const double u = d.dot(t1), v = d.dot(t2);
    Eigen::Matrix<double, 6, 1> basis;
    basis << 1, u, v, u * u, u * v, v * v;
    const double w = around.weights[i];
    for (int r = 0; r < 6; ++r) // the lower triangle (Eigen's rankUpdate is slow at this size)
    {
      for (int k = 0; k <= r; ++k)
      {
        normalMatrix(r, k) += w * basis[r] * basis[k];
      }
    }
    rhs += w * d.dot(patch.plane.normal) * basis;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>, Eigen::Lower> solver(normalMatrix);
  const auto pivots = solver.vectorD();
  // Too few or too clustered points for a quadric: the plane alone.
  if (solver.info() == Eigen::Success && pivots.minCoeff() > kMinPivot * pivots.maxCoeff())
  {
    patch.quadric = solver.solve(rhs);
  }
}

bool PointSurface::surrounds(const Neighbourhood& around, const Patch& patch)
{
  const auto [t1, t2] = tangents(patch.plane.normal);
  const double nearby = 2 * patch.width;
  thread_local std::vector<double> angles;
  angles.clear();
  for (const Vec3& d : around.offsets)
  {
    const double u = d.dot(t1), v = d.dot(t2);
    if (u * u + v * v < nearby * nearby && u * u + v * v > 0)
    {
      angles.push_back(std::atan2(v, u));
    }
  }
  if (angles.size() < 3)
  {
    return false;
  }
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i)
  {
    gap = std::max(gap, angles[i] - angles[i - 1]);
  }
  return gap < kMaxAngularGap;
}

bool PointSurface::fitPlaneAround(
  const Vec3& centre, const Scale& scale, Neighbourhood& around, Patch& patch) const
{
  this->gather(centre, scale, around);
  if (!fit(around, patch.plane))
  {
    return false;
  }
  patch.centre = centre;
  patch.width = scale.width;
  return true;
}

bool PointSurface::leans(const Patch& patch)
{
  return leanInPlane(patch.plane.centroid, patch.centre, patch.plane.normal).norm() >
    kEvenLean * patch.width;
}

int PointSurface::flatScale(
  const Vec3& centre, Neighbourhood& around, Patch& patch, int from, int to) const
{
  for (int s = from; s < std::min(to, static_cast<int>(this->Scales.size())); ++s)
  {
    if (this->fitPlaneAround(centre, *this->Scales[s], around, patch))
    {
      return s;
    }
  }
  return -1;
}

void PointSurface::measureTypical()
{
  const PointList& all = this->Points->points();
  const int none = static_cast<int>(this->Scales.size());
  std::vector<int> sample;
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    if (inSample(i, kTypicalSample))
    {
      sample.push_back(static_cast<int>(i));
    }
  }
  std::vector<int> scales(sample.size());
  std::vector<double> roughnesses(sample.size(), -1); // -1: no plane fits
  parallelFor(0, static_cast<Index>(sample.size()), 0, [&](Index b, Index e) {
    Neighbourhood around;
    for (Index k = b; k < e; ++k)
    {
      Patch patch;
      const int s = this->flatScale(all[sample[k]], around, patch);
      scales[k] = s >= 0 ? s : none;
      if (s >= 0)
      {
        fitQuadric(around, patch);
        roughnesses[k] = roughness(around, patch);
      }
    }
  });
  std::vector<double> noise;
  std::copy_if(roughnesses.begin(), roughnesses.end(), std::back_inserter(noise),
    [](double r) { return r >= 0; });
  const auto lowerMedian = [](auto& values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  this->TypicalScale = scales.empty() ? 0 : std::min(lowerMedian(scales), none - 1);
  this->TypicalNoise = noise.empty() ? 0.0 : lowerMedian(noise);
}

double PointSurface::roughness(const Neighbourhood& around, const Patch& patch)
{
  const Vec3 shift = around.centre - patch.plane.centroid;
  const auto [t1, t2] = tangents(patch.plane.normal);
  double total = 0, squares = 0;
  for (std::size_t i = 0; i < around.offsets.size(); ++i)
  {
    const Vec3 d = around.offsets[i] + shift;
    const double u = d.dot(t1) / patch.width, v = d.dot(t2) / patch.width;
    Eigen::Matrix<double, 6, 1> basis;
    basis << 1, u, v, u * u, u * v, v * v;
    const double height = d.dot(patch.plane.normal) - patch.quadric.dot(basis) * patch.width;
    total += around.weights[i];
    squares += around.weights[i] * height * height;
  }
  return total > 0 ? std::sqrt(squares / total) : 0.0;
}

void PointSurface::finishPatch(const Neighbourhood& around, Patch& patch)
{
  fitQuadric(around, patch);
  // Only a lean beyond an even sample's fades the trust (trustAt); only then is it asked whether
  // the points lie all around.
  patch.surrounded = leans(patch) && surrounds(around, patch);
}

bool PointSurface::fitAround(const Vec3& centre, const Scale& scale, Patch& patch) const
{
  thread_local Neighbourhood around;
  if (!this->fitPlaneAround(centre, scale, around, patch))
  {
    return false;
  }
  finishPatch(around, patch);
  return true;
}

PointSurface::Patch PointSurface::fitPatch(int id) const
{
  thread_local Neighbourhood around;
  Patch patch;
  // From the width most of the cloud needs: on a noisy cloud a finer fit is the noise's fluke (and
  // each finer fit tried first fails on most points); finer ones only where none from it fits (a
  // part thinner than it).
  const Vec3& centre = this->Points->points()[id];
  if (this->flatScale(centre, around, patch, this->TypicalScale) < 0 &&
    this->flatScale(centre, around, patch, 0, this->TypicalScale) < 0)
  {
    // No plane: the weighted centroid of the last neighbourhood tried (fit keeps it), inside the
    // thin part's curve, gives firstLayer its line of sight.
    Patch none;
    none.centre = centre;
    none.plane.centroid = patch.plane.centroid;
    return none;
  }
  finishPatch(around, patch);
  return patch;
}

PointSurface::Patch PointSurface::patchAt(int id) const
{
  enum : std::uint32_t
  {
    Empty,
    Busy,
    First
  }; // a slot from First on holds the patch's place + First
  std::atomic<std::uint32_t>& slot = this->Slots[id];
  if (const std::uint32_t held = slot.load(std::memory_order_acquire); held >= First)
  {
    const std::uint32_t place = held - First;
    return this->Chunks[place / Chunk::kSize]
      .load(std::memory_order_acquire)
      ->patches[place % Chunk::kSize];
  }
  const Patch patch = this->fitPatch(id);
  // The first thread to finish stores it; one that meets another storing keeps its own equal copy.
  std::uint32_t expected = Empty;
  if (slot.compare_exchange_strong(expected, Busy, std::memory_order_acq_rel))
  {
    const std::uint32_t place = this->Stored.fetch_add(1, std::memory_order_relaxed);
    std::atomic<Chunk*>& chunkSlot = this->Chunks[place / Chunk::kSize];
    Chunk* chunk = chunkSlot.load(std::memory_order_acquire);
    if (!chunk)
    {
      auto made = std::make_unique<Chunk>();
      if (chunkSlot.compare_exchange_strong(chunk, made.get(), std::memory_order_acq_rel))
      {
        chunk = made.release();
      } // else another thread made it first: `chunk` is that one
    }
    chunk->patches[place % Chunk::kSize] = patch;
    slot.store(place + First, std::memory_order_release);
  }
  return patch;
}

double PointSurface::trustAt(const Vec3& x, const Patch& patch)
{
  // Full while x's foot lies among the points, none once their centroid is kMaxOffCentre widths to
  // one side of it (beyond a gap's rim), fading in between. A patch's centre leans away from a rim
  // (its points' centroid lies about h / sqrt(pi) inwards); from a centre that leans so, a foot
  // further out adds its distance, while beside a centre among evenly spread points it does not.
  const double width = patch.width;
  const Plane& plane = patch.plane;
  const Vec3 fromCentroid =
    (x - plane.centroid) - (x - plane.centroid).dot(plane.normal) * plane.normal;
  const Vec3 lean = leanInPlane(plane.centroid, patch.centre, plane.normal);
  const double leanLength = lean.norm();
  const double oneSided =
    std::clamp((leanLength - kEvenLean * width) / ((kRimLean - kEvenLean) * width), 0.0, 1.0);
  const double outwards =
    oneSided > 0 ? std::max(0.0, -fromCentroid.dot(lean) / leanLength - leanLength) : 0.0;
  const double offCentre = patch.surrounded ? 0.0 : leanLength + oneSided * outwards;
  const Vec3 fromCentre = fromCentroid + lean;
  return fromCentre.squaredNorm() > kNearAnchor * kNearAnchor * width * width
    ? 0.0
    : std::clamp(2 - offCentre / (0.5 * kMaxOffCentre * width), 0.0, 1.0);
}

SourcePoint PointSurface::nearestPoint(const Vec3& x, double maxSquaredDistance) const
{
  // A wrap's vertices mostly lie within a width of a point: the finest scale's bins (all points,
  // side by side) hold every point that near, read in a few runs of memory, where the k-d tree's
  // descent waits on memory at every level. Nearer than the radius, the nearest found is the
  // nearest.
  const Scale& finest = *this->Scales.front();
  const double radius = std::min(finest.width, std::sqrt(maxSquaredDistance));
  SourcePoint p;
  p.sure = false; // a point has no sides
  p.found = finest.grid.nearest(x, radius, p.element, p.point, p.squaredDistance);
  return p.found ? p : this->Points->closestPoint(x, maxSquaredDistance);
}

void PointSurface::fitWeights(
  const Vec3& x, std::vector<int>& ids, std::vector<double>& weights) const
{
  ids.clear();
  weights.clear();
  const SourcePoint nearest = this->nearestPoint(x, std::numeric_limits<double>::infinity());
  if (!nearest.found)
  {
    return;
  }
  // Centred on x's surface point (where the fit is trusted), else on the nearest point.
  const Patch patch = this->patchAt(nearest.element);
  const SourcePoint foot = this->closestPoint(x, std::numeric_limits<double>::infinity());
  const Vec3 centre = foot.found && foot.trust > 0 ? foot.point : nearest.point;
  const Scale& finest = *this->Scales.front(); // every point, by its input index
  const double width = patch.width > 0 ? patch.width : finest.width;
  const double inverse = 1 / (width * width);
  double total = 0;
  finest.grid.forEachWithin(centre, kCutoff * width, [&](int id, const Vec3& point) {
    ids.push_back(id);
    weights.push_back(std::exp(-(point - centre).squaredNorm() * inverse));
    total += weights.back();
  });
  if (!(total > 0))
  {
    ids.assign(1, nearest.element);
    weights.assign(1, 1.0);
    return;
  }
  for (double& w : weights)
  {
    w /= total;
  }
}

SourcePoint PointSurface::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  const SourcePoint nearest = this->nearestPoint(x, maxSquaredDistance);
  if (!nearest.found)
  {
    return nearest;
  }
  Patch patch = this->patchAt(nearest.element);
  if (!(patch.width > 0))
  {
    return this->firstLayer(x, nearest, patch.plane.centroid);
  }
  // The patch's point stands for the points around x while x's foot lies near it and its neighbours
  // spread evenly around (full trust). A foot further out (over a sampling hole) or a point that
  // leans (near a rim) gets a patch of its own, centred on the foot, at the same scale.
  double trust = this->trustAt(x, patch);
  if (trust < 1)
  {
    const Vec3 foot = x - (x - patch.plane.centroid).dot(patch.plane.normal) * patch.plane.normal;
    const Scale& scale = **std::find_if(this->Scales.begin(), this->Scales.end(),
      [&](const auto& s) { return s->width == patch.width; });
    trust = this->fitAround(foot, scale, patch) ? this->trustAt(x, patch) : 0.0;
  }
  if (trust <= 0)
  {
    return SourcePoint();
  }
  const double width = patch.width;
  const Plane& plane = patch.plane;
  const Vec3 foot = x - (x - plane.centroid).dot(plane.normal) * plane.normal;
  const Vec3 fromCentroid = foot - plane.centroid; // in the plane
  const auto [t1, t2] = tangents(plane.normal);
  const double u = fromCentroid.dot(t1) / width, v = fromCentroid.dot(t2) / width;
  Eigen::Matrix<double, 6, 1> basis;
  basis << 1, u, v, u * u, u * v, v * v;
  // A quadric lifts a curved surface off its plane by about h^2 times the curvature; more is an
  // extrapolation into a gap between the points, where the plane is the safer guess.
  const double lift = patch.quadric.dot(basis) * width;
  SourcePoint p = nearest;
  p.point = foot + (std::abs(lift) <= kMaxLift * width ? lift : 0.0) * plane.normal;
  p.squaredDistance = (x - p.point).squaredNorm();
  p.normal = plane.normal;
  p.side = 0;
  p.trust = trust;
  return p;
}

SourcePoint PointSurface::firstLayer(
  const Vec3& x, const SourcePoint& nearest, const Vec3& inside) const
{
  const Scale& finest = *this->Scales.front();
  const double d = (x - inside).norm();
  if (this->TypicalScale == 0 || !(d > 1e-9 * finest.width))
  {
    return SourcePoint();
  }
  // The line of sight runs from the points' centroid (inside the part's curve) towards x: from the
  // nearest point it would run along the noise wherever x lies within it.
  const Vec3 n = (x - inside) / d;
  const double radius = kLayerRadius * finest.width, depth = kLayerDepth * this->TypicalNoise;
  // The points near that line, from a ball about the nearest point that reaches the layer's depth
  // and as far back past x: where the line meets points beyond x too (x in a fold, between parts),
  // the layer starts behind x and puts it inside, and the caller's closed field decides.
  thread_local std::vector<double> depths;
  depths.clear();
  double shallowest = std::numeric_limits<double>::infinity();
  const double reach = std::sqrt(radius * radius + (radius + depth) * (radius + depth));
  finest.grid.forEachWithinNearLine(nearest.point, reach, x, n, radius, [&](int, const Vec3& q) {
    const Vec3 v = x - q;
    const double t = v.dot(n);
    if (v.squaredNorm() - t * t <= radius * radius)
    {
      depths.push_back(t);
      shallowest = std::min(shallowest, t);
    }
  });
  double sum = 0;
  int count = 0;
  for (const double t : depths)
  {
    if (t <= shallowest + depth)
    {
      sum += t;
      ++count;
    }
  }
  if (count < kMinLayerPoints)
  {
    return SourcePoint();
  }
  // A negative mean: x lies within the layer, deeper than its middle.
  const double mean = sum / count;
  SourcePoint p = nearest;
  p.point = x - mean * n;
  p.squaredDistance = mean * mean;
  p.normal = n;
  p.side = 0;
  p.beyondEstimate = true;
  return p;
}

bool PointSurface::onRim(const Vec3& centre, int from, Vec3& onPlane) const
{
  thread_local Neighbourhood around;
  Patch patch; // its plane only: a rim needs no quadric
  if (this->flatScale(centre, around, patch, from) < 0 || !leans(patch))
  {
    return false;
  }
  // Points spread off their plane even at the width where it shows (a crease, a thin part's end)
  // are no rim: their RMS height over it (the patch's quadric is zero). A noisy rim point lies off
  // the sheet by its noise; its plane's point does not.
  onPlane = centre - (centre - patch.plane.centroid).dot(patch.plane.normal) * patch.plane.normal;
  return roughness(around, patch) <= kMaxRimSpread * patch.width && !surrounds(around, patch);
}

std::vector<std::array<Vec3, 2>> PointSurface::rims(
  double /*creaseAngle: points have no creases*/) const
{
  const Scale& finest = *this->Scales.front();
  const PointList& all = this->Points->points();
  // Noisy points look flat only at a coarser width: the search starts at the one most of them need
  // (each finer width's fit fails on them first; at 200,000 noisy points, a 0.6 s search).
  const int from = this->typicalFlatScale();
  std::vector<Vec3> onPlane;
  auto test = [&](const std::vector<int>& ids) {
    std::vector<char> rim(ids.size(), 0);
    onPlane.resize(ids.size());
    parallelFor(0, static_cast<long long>(ids.size()), 0, [&](long long b, long long e) {
      for (long long k = b; k < e; ++k)
      {
        rim[k] = this->onRim(all[ids[k]], from, onPlane[k]);
      }
    });
    return rim;
  };
  // Rims are a small part of a cloud: the sample of the scale after the one they are tested at (one
  // point in four on clean points) finds them, then the points near each one found are asked, round
  // after round along the rim.
  std::vector<int> asking;
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    if (inSample(i, from + 1))
    {
      asking.push_back(static_cast<int>(i));
    }
  }
  std::vector<char> asked(all.size(), 0);
  for (const int id : asking)
  {
    asked[id] = 1;
  }
  std::vector<std::array<Vec3, 2>> rims;
  while (!asking.empty())
  {
    const std::vector<char> found = test(asking);
    std::vector<int> next;
    for (std::size_t k = 0; k < asking.size(); ++k)
    {
      if (!found[k])
      {
        continue;
      }
      rims.push_back({ onPlane[k], onPlane[k] });
      const Vec3& p = all[asking[k]];
      finest.grid.forEachWithin(p, kRimReach * finest.width, [&](int id, const Vec3&) {
        if (!asked[id])
        {
          asked[id] = 1;
          next.push_back(id);
        }
      });
    }
    asking.swap(next);
  }
  return rims;
}

} // namespace shrinkwrap
