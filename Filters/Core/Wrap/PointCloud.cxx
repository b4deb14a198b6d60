#include "Wrap/PointCloud.h"

#include <Eigen/Eigenvalues>

#include <array>
#include <limits>

namespace shrinkwrap
{

namespace
{
// The width of the fitted surface's weights, in median neighbour distances: a few rings of
// neighbours, narrow enough that curvature biases the fit little.
constexpr double kFitWidthPerSpacing = 3;
} // namespace

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
    cloud.surface =
      std::make_shared<const PointSurface>(cloud.points, kFitWidthPerSpacing * cloud.spacing);
  }
  return cloud;
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
    return Status::failure("the points lie on a line, so they enclose nothing to wrap (Mesh Signed "
                           "Distance measures the distance to them)");
  if (extent[0] <= tolerance)
    return Status::failure(
      "the points lie in a plane, so they enclose nothing to wrap (Mesh Signed "
      "Distance measures the distance to them)");
  return {};
}

} // namespace shrinkwrap
