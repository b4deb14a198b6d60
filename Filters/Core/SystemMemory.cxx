#include "SystemMemory.h"

#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

namespace shrinkwrap
{

std::int64_t availableMemoryBytes()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::int64_t kib;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kib * 1024;
    }
  }
#if defined(_SC_AVPHYS_PAGES) && defined(_SC_PAGESIZE)
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && size > 0)
  {
    return static_cast<std::int64_t>(pages) * size;
  }
#endif
  return std::numeric_limits<std::int64_t>::max();
}

} // namespace shrinkwrap
