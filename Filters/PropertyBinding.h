// Between a filter's properties and the core's settings they stand for: one value at a time, by
// type: enums as their numbers, a size the settings leave unset (automatic) as 0, a switch as 0 or
// 1, a pair as two numbers. A filter lists its properties beside their settings once
// (vtkShrinkWrapFilter::BindProperties) and reads that list both ways and in PrintSelf.
#ifndef ShrinkWrap_PropertyBinding_h
#define ShrinkWrap_PropertyBinding_h

#include "Common/Status.h"

#include <vtkIndent.h>

#include <algorithm>
#include <optional>
#include <ostream>
#include <type_traits>

namespace shrinkwrap
{
namespace convert
{

// No upper limit (a size in the target's units): the panel's range has no max.
constexpr double kNoLimit = 1e30;

// A property as the panel shows it: its name (the XML's, Python's and the C++ Set/Get's), its
// label, the unit its documentation states ("" where it has none: a switch, a choice, a count), the
// range the panel allows (every component of a pair or triple; a switch 0 to 1, a choice its first
// to last entry), and what 0 means where it means something else than a size of 0.
struct PropertyInfo
{
  const char* name;
  const char* label;
  const char* unit;
  double min;
  double max;
  const char* zero = nullptr; // e.g. "automatic"
};

// Why `value` is outside the property's range, in the panel's words; ok when it is inside.
Status checkRange(const PropertyInfo& info, double value);

template <typename T>
Status checkProperty(const PropertyInfo& info, const T& value)
{
  if constexpr (std::is_array_v<T>)
  {
    for (const auto& v : value)
    {
      if (Status checked = checkRange(info, static_cast<double>(v)); !checked)
      {
        return checked;
      }
    }
    return {};
  }
  else
  {
    return checkRange(info, static_cast<double>(value));
  }
}

template <typename T>
struct IsOptional : std::false_type
{
};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type
{
};

template <typename To, typename From>
void assign(To& to, const From& from)
{
  if constexpr (IsOptional<From>::value)
  {
    to = from.value_or(0);
  }
  else if constexpr (IsOptional<To>::value)
  {
    to = from != 0 ? To(from) : To(); // a negative value is the settings' to refuse
  }
  else if constexpr (std::is_array_v<To>)
  {
    std::copy(from.begin(), from.end(), to);
  }
  else if constexpr (std::is_array_v<From>)
  {
    std::copy(from, from + to.size(), to.begin());
  }
  else
  {
    to = static_cast<To>(from);
  }
}

// "Name: value" (a pair as two numbers), a line of PrintSelf.
template <typename T>
void printProperty(std::ostream& os, const char* name, const T& value)
{
  os << name << ":";
  if constexpr (std::is_array_v<T>)
  {
    for (const auto& v : value)
    {
      os << " " << v;
    }
  }
  else
  {
    os << " " << value;
  }
  os << "\n";
}

// A bind for BindProperties that prints each property as a line of PrintSelf.
inline auto propertyPrinter(std::ostream& os, vtkIndent indent)
{
  return [&os, indent](const PropertyInfo& info, const auto& property, const auto&) {
    os << indent;
    printProperty(os, info.name, property);
  };
}

} // namespace convert
} // namespace shrinkwrap

#endif
