#include "GapClosing.h"

#include "SignedDistance.h"
#include "SurfaceMesh.h"

namespace shrinkwrap
{

Status closingField(const DistanceGrid& field, double radius, const Contour& contour, DistanceGrid& closed)
{
  if (!(radius >= 0.25 * field.lattice().spacing.minCoeff()))
  {
    closed = field;
    return {};
  }
  const TriangleSurface dilated = contour(field, radius);
  SurfaceMesh check;
  if (dilated.triangles.empty() || !SurfaceMesh::build(dilated.points, dilated.triangles, check))
  {
    return Status::failure("the target dilated by half the Gap Size is empty or reaches the border of the "
                           "distance field; lower the Gap Size, or enlarge the field");
  }
  std::vector<float> distance(field.lattice().nodeCount());
  const SignedDistanceResult result =
    computeSignedDistance(dilated, field.lattice(), SignedDistanceSettings(), distance.data());
  if (!result.isSigned)
  {
    return Status::failure("the distance to the target dilated by half the Gap Size has no sign");
  }
  for (float& d : distance)
  {
    d += static_cast<float>(radius);
  }
  closed = DistanceGrid(field.lattice(), std::move(distance));
  return {};
}

} // namespace shrinkwrap
