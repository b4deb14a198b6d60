#include "Wrap/WrapSettings.h"

#include <cmath>

namespace shrinkwrap
{

namespace
{
bool positiveOrUnset(const std::optional<double>& size)
{
  return !size || (*size > 0 && std::isfinite(*size));
}
} // namespace

Status WrapSettings::validate() const
{
  if (!(this->evolution.timeStep > 0) || !std::isfinite(this->evolution.timeStep))
    return Status::failure("Time Per Step must be positive");
  if (this->start.subdivision < 0 || this->start.subdivision > 8)
    return Status::failure("Subdivision Level must be between 0 and 8");
  if (!positiveOrUnset(this->targetEdgeLength))
    return Status::failure("Target Edge Length must be positive (0: automatic)");
  if (!positiveOrUnset(this->gapSize))
    return Status::failure("Gap Size must be positive (0: automatic)");
  const auto& range = this->edgeLengthRange;
  if (!(range[0] >= kShortestEdge && range[0] <= 1 && range[1] >= 1 && range[1] <= kLongestEdge))
    return Status::failure("Edge Length Range must hold 1: from 0.1 to 1, then from 1 to 4 (times "
                           "the Target Edge Length)");
  if (!(this->evolution.rims.creaseAngle >= 0 && this->evolution.rims.creaseAngle <= 180))
    return Status::failure("Crease Angle must be between 0 and 180 degrees");
  return {};
}

} // namespace shrinkwrap
