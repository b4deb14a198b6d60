// LargeVector (HugePages.h): buffers from a quarter of a huge page up come from their own mapping,
// aligned to a huge page, where mapsLargeBuffers(); smaller ones, and all elsewhere, from the heap.
// Growing across that size, shrinking back, copying and moving keep every value (a buffer freed the
// wrong way would crash here, and under AddressSanitizer would be reported); sizes no mapping can
// hold throw std::bad_alloc.
#include "Common/HugePages.h"
#include "TestUtilities.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>

namespace
{
using namespace shrinkwrap;

bool holdsIndices(const LargeVector<std::int64_t>& v)
{
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    if (v[i] != static_cast<std::int64_t>(i))
    {
      return false;
    }
  }
  return true;
}

bool alignedToHugePage(const void* p)
{
  return reinterpret_cast<std::uintptr_t>(p) % kHugePage == 0;
}
} // namespace

int TestHugePages(int, char*[])
{
  const std::size_t large = kMinHugeBuffer / sizeof(std::int64_t); // the first size in huge pages
  const bool mapped = mapsLargeBuffers();
  LargeVector<std::int64_t> v;
  // Grown one by one from empty to three huge pages: reallocated across the threshold many times.
  for (std::size_t i = 0; i < 3 * kHugePage / sizeof(std::int64_t) + 5; ++i)
  {
    v.push_back(static_cast<std::int64_t>(i));
  }
  SW_CHECK(holdsIndices(v), "growing across the threshold keeps every value");
  SW_CHECK(!mapped || alignedToHugePage(v.data()), "a large buffer starts on a huge page");

  v.resize(large - 1);
  v.shrink_to_fit(); // back to the heap
  SW_CHECK(
    v.size() == large - 1 && holdsIndices(v), "shrinking below the threshold keeps every value");

  LargeVector<std::int64_t> copy = v;
  copy.resize(2 * large);
  for (std::size_t i = large - 1; i < copy.size(); ++i)
  {
    copy[i] = static_cast<std::int64_t>(i);
  }
  SW_CHECK(holdsIndices(copy) && holdsIndices(v), "a copy grown past the threshold is its own");
  SW_CHECK(!mapped || alignedToHugePage(copy.data()), "so is its buffer");

  LargeVector<std::int64_t> moved = std::move(copy);
  SW_CHECK(moved.size() == 2 * large && holdsIndices(moved), "a move takes the buffer over");

  // A buffer of exactly the threshold and one of many huge pages, written to the last element.
  LargeVector<char> edge(kMinHugeBuffer, 1), big(5 * kHugePage + 3, 2);
  SW_CHECK(edge.back() == 1 && big.back() == 2 && big.front() == 2, "the whole buffer is usable");

  // A buffer for a library that frees with std::free (VTK's arrays): aligned where large, whole,
  // and freed so (AddressSanitizer reports a buffer freed the wrong way).
  for (const std::size_t bytes : { std::size_t(100), kMinHugeBuffer, 3 * kHugePage + 7 })
  {
    auto* freeable = static_cast<char*>(allocateFreeable(bytes));
    SW_CHECK(freeable != nullptr, "allocateFreeable(" << bytes << ") gives a buffer");
    SW_CHECK(!mapped || bytes < kMinHugeBuffer || alignedToHugePage(freeable),
      "a large freeable buffer starts on a huge page");
    std::fill(freeable, freeable + bytes, char(3));
    SW_CHECK(freeable[0] == 3 && freeable[bytes - 1] == 3, "the whole freeable buffer is usable");
    std::free(freeable);
  }

  // Sizes no mapping can hold are refused, not rounded into a small one: one whose rounding up to
  // huge pages would wrap, one beyond the address space.
  for (const std::size_t bytes :
    { std::numeric_limits<std::size_t>::max() - 100, std::size_t(1) << 50 })
  {
    bool refused = false;
    try
    {
      unmapHugePages(mapHugePages(bytes), bytes);
    }
    catch (const std::bad_alloc&)
    {
      refused = true;
    }
    SW_CHECK(refused, "mapping " << bytes << " bytes throws std::bad_alloc");
  }
  return testing::finish("TestHugePages");
}
