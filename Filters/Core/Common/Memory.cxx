#include "Common/Memory.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace shrinkwrap
{

namespace
{
constexpr double kUnknown = std::numeric_limits<double>::infinity();

// The value of `key` in a "key: value kB" file (/proc/meminfo, /proc/self/status), in bytes.
double kibibyteEntry(const char* file, const std::string& key)
{
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      std::istringstream value(line.substr(key.size()));
      double kib = 0;
      return value >> kib ? 1024 * kib : kUnknown;
    }
  }
  return kUnknown;
}

// A number in a cgroup file ("max" or no file: no limit).
double cgroupValue(const std::string& file)
{
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text == "max")
  {
    return kUnknown;
  }
  std::istringstream value(text);
  double bytes = 0;
  return value >> bytes ? bytes : kUnknown;
}

// The process's cgroup (v2) folder, from /proc/self/cgroup's "0::/path" line.
std::string cgroupFolder()
{
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, 3, "0::") == 0)
    {
      return "/sys/fs/cgroup" + line.substr(3);
    }
  }
  return {};
}
} // namespace

double availableMemory()
{
  double available = kibibyteEntry("/proc/meminfo", "MemAvailable:");
#if defined(__linux__)
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    const double mapped = kibibyteEntry("/proc/self/status", "VmSize:");
    const double left = static_cast<double>(limit.rlim_cur) - (mapped < kUnknown ? mapped : 0);
    available = std::min(available, std::max(left, 0.0));
  }
  if (const std::string group = cgroupFolder(); !group.empty())
  {
    const double cap = cgroupValue(group + "/memory.max");
    const double used = cgroupValue(group + "/memory.current");
    if (cap < kUnknown)
    {
      available = std::min(available, std::max(cap - (used < kUnknown ? used : 0), 0.0));
    }
  }
#endif
  return available;
}

} // namespace shrinkwrap
