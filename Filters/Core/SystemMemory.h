// How much memory the machine can still give, to refuse a grid before allocating it.
#ifndef ShrinkWrap_SystemMemory_h
#define ShrinkWrap_SystemMemory_h

#include <cstdint>

namespace shrinkwrap
{

// MemAvailable from /proc/meminfo, else free physical pages; the largest int64 if neither is known.
std::int64_t availableMemoryBytes();

} // namespace shrinkwrap

#endif
