#include "PointSurface.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace shrinkwrap
{

namespace
{
constexpr int kScales = 3;             // widths h, 2 h, 4 h
constexpr double kCutoff = 2.5;        // neighbours within this many widths (weights below 0.002 beyond)
constexpr double kMinWeight = 1;       // a fit needs the weight of at least one point at the centre
// In widths, the points' centroid beside the foot (along the plane): up to half of this the fit is
// trusted fully, beyond this not at all (a one-sided fit). Sampling holes of a random sample (up to
// about 3.5 neighbour distances, more than h) need the full trust; a fit beyond a gap's rim does not.
constexpr double kMaxOffCentre = 1.0;
constexpr double kMaxFlatness = 0.25;  // smallest over middle eigenvalue: above it, no plane
constexpr double kMinPivot = 1e-6;     // of the quadric's normal equations, relative to the largest
constexpr double kMaxLift = 0.2;       // in widths: the most a quadric may move the plane's surface point
} // namespace

PointSurface::Scale::Scale(std::vector<Vec3> sample, double w)
  : width(w)
  , points(std::move(sample))
  , grid(this->points, kCutoff * w)
{
}

PointSurface::PointSurface(std::shared_ptr<const PointSource> points, double width)
  : Points(std::move(points))
{
  const std::vector<Vec3>& all = this->Points->points();
  for (int s = 0; s < kScales; ++s)
  {
    // One point in 4^s, picked by a hash of its index (not by stride: a scanner's order has rows).
    const std::uint64_t mask = (std::uint64_t(1) << (2 * s)) - 1;
    std::vector<Vec3> sample;
    sample.reserve(all.size() >> (2 * s));
    for (std::size_t i = 0; i < all.size(); ++i)
    {
      if ((((i + 1) * 0x9E3779B97F4A7C15ull) >> 40 & mask) == 0)
      {
        sample.push_back(all[i]);
      }
    }
    this->Scales.push_back(std::make_unique<const Scale>(std::move(sample), width * (1 << s)));
  }
}

void PointSurface::gather(const Vec3& centre, const Scale& scale, Neighbourhood& around) const
{
  around.centre = centre;
  around.offsets.clear();
  around.weights.clear();
  const std::vector<Vec3>& points = scale.points;
  const double inverse = 1 / (scale.width * scale.width);
  scale.grid.forEachWithin(centre, kCutoff * scale.width, [&](int id) {
    const Vec3 d = points[id] - centre;
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
  if (!(total >= kMinWeight))
  {
    return false;
  }
  const Vec3 mean = sum / total;
  const Eigen::Matrix3d covariance = moments / total - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes;
  axes.computeDirect(covariance);
  const Eigen::Vector3d& lambda = axes.eigenvalues(); // ascending
  if (!(lambda[0] <= kMaxFlatness * lambda[1]))
  {
    return false;
  }
  plane.centroid = around.centre + mean;
  plane.normal = axes.eigenvectors().col(0).normalized();
  return true;
}

double PointSurface::height(const Neighbourhood& around, const Vec3& foot, const Plane& plane, double width)
{
  // Heights over the plane, in widths, fitted by w = a0 + a1 u + a2 v + a3 u^2 + a4 u v + a5 v^2 about
  // the foot (u = v = 0): a0 is the surface's height there.
  const Vec3 t1 = plane.normal.unitOrthogonal();
  const Vec3 t2 = plane.normal.cross(t1);
  Eigen::Matrix<double, 6, 6> normalMatrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  const double scale = 1 / width;
  const Vec3 shift = around.centre - foot;
  for (std::size_t i = 0; i < around.offsets.size(); ++i)
  {
    const Vec3 d = (around.offsets[i] + shift) * scale;
    const double u = d.dot(t1), v = d.dot(t2);
    Eigen::Matrix<double, 6, 1> basis;
    basis << 1, u, v, u * u, u * v, v * v;
    const double w = around.weights[i];
    normalMatrix.selfadjointView<Eigen::Lower>().rankUpdate(basis, w);
    rhs += w * d.dot(plane.normal) * basis;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>, Eigen::Lower> solver(normalMatrix);
  const auto pivots = solver.vectorD();
  const double planeHeight = (plane.centroid - foot).dot(plane.normal);
  // Too few or too clustered points for a quadric: the plane's own height.
  if (solver.info() != Eigen::Success || !(pivots.minCoeff() > kMinPivot * pivots.maxCoeff()))
  {
    return planeHeight;
  }
  // A quadric lifts a curved surface off its plane by about h^2 times the curvature; more is an
  // extrapolation into a gap between the points, where the plane is the safer guess.
  const double lifted = solver.solve(rhs)[0] * width;
  return std::abs(lifted - planeHeight) <= kMaxLift * width ? lifted : planeHeight;
}

SourcePoint PointSurface::closestPoint(const Vec3& x, double maxSquaredDistance) const
{
  thread_local Neighbourhood around;
  const SourcePoint nearest = this->Points->closestPoint(x, maxSquaredDistance);
  const SourcePoint none;
  Plane plane;
  if (!nearest.found)
  {
    return none;
  }
  // The finest scale at which the points around the nearest one look flat: noise thicker than a
  // fraction of the width hides the plane until the width outgrows it.
  const Scale* scale = nullptr;
  for (const auto& s : this->Scales)
  {
    this->gather(nearest.point, *s, around);
    if (fit(around, plane))
    {
      scale = s.get();
      break;
    }
  }
  if (!scale)
  {
    return none;
  }
  const double width = scale->width;
  // Refitted about the foot: the weights then centre where the surface point is.
  this->gather(x - (x - plane.centroid).dot(plane.normal) * plane.normal, *scale, around);
  if (!fit(around, plane))
  {
    return none;
  }
  Vec3 foot = x - (x - plane.centroid).dot(plane.normal) * plane.normal;
  const Vec3 along = (plane.centroid - foot) - (plane.centroid - foot).dot(plane.normal) * plane.normal;
  // Trusted fully while the points lie around the foot, not at all once their centroid is
  // kMaxOffCentre widths to one side (a gap's rim), fading in between.
  const double trust = std::clamp(2 - along.norm() / (0.5 * kMaxOffCentre * width), 0.0, 1.0);
  if (trust <= 0)
  {
    return none;
  }
  foot += height(around, foot, plane, width) * plane.normal;
  SourcePoint p = nearest;
  p.point = foot;
  p.squaredDistance = (x - foot).squaredNorm();
  p.normal = plane.normal;
  p.side = 0;
  p.trust = trust;
  return p;
}

} // namespace shrinkwrap
