// Large buffers in 2 MiB pages. Fresh memory is faulted in a page at a time on its first write, and
// on a virtual machine a 4 KiB page's fault is slow; Linux's transparent huge pages, asked for by
// madvise (Debian's default mode), fault in 2 MiB at a time for about the cost of one small page.
// Buffers under kMinHugeBuffer, systems other than Linux, kernels that give no huge pages and
// AddressSanitizer builds get ordinary memory.
#ifndef ShrinkWrap_HugePages_h
#define ShrinkWrap_HugePages_h

#include <cstddef>
#include <memory>
#include <vector>

namespace shrinkwrap
{

constexpr std::size_t kHugePage = std::size_t(2) << 20;
// A quarter of a huge page and up: one fault of 2 MiB costs less than 64 of 4 KiB.
constexpr std::size_t kMinHugeBuffer = kHugePage / 4;

// Pages of at least `bytes` (rounded up to huge pages), aligned to kHugePage and advised to be
// huge; throws std::bad_alloc when none are left. Only where mapsLargeBuffers().
void* mapHugePages(std::size_t bytes);
void unmapHugePages(void* p, std::size_t bytes);
// Whether buffers of kMinHugeBuffer and more are mapped: on Linux where the kernel gives huge pages
// to a mapping that asks (transparent huge pages not "never"; read once, so a buffer is always
// freed the way it was allocated), and not under AddressSanitizer, which checks the heap's bounds
// but not a mapping's. Without huge pages a mapped buffer would be faulted in anew at every wrap
// where the heap's is reused.
bool mapsLargeBuffers();

// At least `bytes` from the C heap, freed by std::free (so a buffer handed to a library that frees
// it so, as VTK's arrays do): aligned to kHugePage and advised to be huge where mapsLargeBuffers()
// and `bytes` is at least kMinHugeBuffer; null when none are left.
void* allocateFreeable(std::size_t bytes);

// A std::allocator that maps buffers of kMinHugeBuffer and more in huge pages (which of the two a
// buffer came from follows from its size alone).
template <typename T>
struct HugePageAllocator
{
  using value_type = T;
  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept
  {
  }
  static bool huge(std::size_t n) { return n * sizeof(T) >= kMinHugeBuffer && mapsLargeBuffers(); }
  T* allocate(std::size_t n)
  {
    return huge(n) ? static_cast<T*>(mapHugePages(n * sizeof(T))) : std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n)
  {
    huge(n) ? unmapHugePages(p, n * sizeof(T)) : std::allocator<T>().deallocate(p, n);
  }
  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const noexcept
  {
    return true;
  }
  template <typename U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept
  {
    return false;
  }
};

// A vector for buffers that may be megabytes: a cloud's points, trees and bins.
template <typename T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

} // namespace shrinkwrap

#endif
