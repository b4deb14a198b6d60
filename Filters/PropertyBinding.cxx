#include "PropertyBinding.h"

#include <cmath>
#include <sstream>

namespace shrinkwrap
{
namespace convert
{

Status checkRange(const PropertyInfo& info, double value)
{
  if (std::isfinite(value) && value >= info.min && value <= info.max)
  {
    return {};
  }
  std::ostringstream s;
  s.precision(12);
  s << info.label << " is " << value << ": it must be ";
  if (info.max >= kNoLimit && info.min <= -kNoLimit)
  {
    s << "a finite number";
  }
  else if (info.max >= kNoLimit)
  {
    s << "at least " << info.min;
  }
  else
  {
    s << "from " << info.min << " to " << info.max;
  }
  if (*info.unit)
  {
    s << " (" << info.unit << ")";
  }
  if (info.zero)
  {
    s << "; 0: " << info.zero;
  }
  return Status::failure(s.str());
}

} // namespace convert
} // namespace shrinkwrap
