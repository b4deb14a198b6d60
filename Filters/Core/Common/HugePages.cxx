#include "Common/HugePages.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <new>
#include <string>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shrinkwrap
{

namespace
{
std::size_t roundedUp(std::size_t bytes)
{
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}
} // namespace

#if defined(__SANITIZE_ADDRESS__)
#define SHRINKWRAP_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHRINKWRAP_ADDRESS_SANITIZER 1
#endif
#endif

#if defined(__linux__)
bool mapsLargeBuffers()
{
#if defined(SHRINKWRAP_ADDRESS_SANITIZER)
  return false;
#else
  static const bool offered = [] {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    return std::getline(mode, line) && line.find("[never]") == std::string::npos;
  }();
  return offered;
#endif
}

void* mapHugePages(std::size_t bytes)
{
  // mmap aligns to small pages only: a huge page more is mapped, and the ends beyond the aligned
  // range given back.
  if (bytes > std::numeric_limits<std::size_t>::max() - 2 * kHugePage) // the rounding would wrap
  {
    throw std::bad_alloc();
  }
  const std::size_t size = roundedUp(bytes);
  void* mapped =
    mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED)
  {
    throw std::bad_alloc();
  }
  const auto start = reinterpret_cast<std::uintptr_t>(mapped);
  const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
  if (aligned > start)
  {
    munmap(mapped, aligned - start);
  }
  if (const std::uintptr_t end = start + size + kHugePage; end > aligned + size)
  {
    munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  }
  void* p = reinterpret_cast<void*>(aligned);
  madvise(p, size, MADV_HUGEPAGE); // a hint: without huge pages the buffer works the same
  return p;
}

void unmapHugePages(void* p, std::size_t bytes)
{
  munmap(p, roundedUp(bytes));
}
void* allocateFreeable(std::size_t bytes)
{
  if (bytes < kMinHugeBuffer || !mapsLargeBuffers() ||
    bytes > std::numeric_limits<std::size_t>::max() - 2 * kHugePage)
  {
    return std::malloc(bytes);
  }
  const std::size_t size = roundedUp(bytes);
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, size) != 0)
  {
    return nullptr;
  }
  madvise(p, size, MADV_HUGEPAGE); // a hint: without huge pages the buffer works the same
  return p;
}
#else
void* allocateFreeable(std::size_t bytes)
{
  return std::malloc(bytes);
}

bool mapsLargeBuffers()
{
  return false;
}

void* mapHugePages(std::size_t)
{
  throw std::bad_alloc();
}

void unmapHugePages(void*, std::size_t) {}
#endif

} // namespace shrinkwrap
