// The step cache: the nearest step at or before a time, triangles shared between steps counted
// once, thinning that keeps step 0, the newest, the one shown and edited steps, and dropping the
// steps after an edit.
#include "Evolution/StepCache.h"
#include "TestUtilities.h"

namespace
{
using namespace shrinkwrap;

StepCache::Step stepOf(int vertices, const StepCache::Triangles& triangles, bool edited = false)
{
  return { std::vector<Vec3>(vertices, Vec3::Zero()), std::vector<Vec3>(vertices, Vec3::Zero()),
    triangles, 1.0, edited };
}

void lookups()
{
  auto triangles = std::make_shared<const std::vector<std::array<int, 3>>>(100);
  StepCache cache;
  for (int k : { 0, 1, 2, 5, 9 })
  {
    cache.store(k, stepOf(50, triangles));
  }
  SW_CHECK(cache.atOrBefore(5).first == 5 && cache.atOrBefore(7).first == 5 &&
      cache.atOrBefore(100).first == 9,
    "the step asked for, else the nearest before it");
  SW_CHECK(cache.newest() == 9, "the newest step");
  const double oneStep = 2.0 * sizeof(Vec3) * 50;
  SW_CHECK(cache.bytes() == 5 * oneStep + 100 * sizeof(std::array<int, 3>),
    "shared triangles counted once");
  cache.dropAfter(2);
  SW_CHECK(cache.newest() == 2 && !cache.has(5) && cache.has(2), "steps after an edit dropped");
}

void thinning()
{
  auto triangles = std::make_shared<const std::vector<std::array<int, 3>>>(10);
  StepCache cache;
  for (int k = 0; k <= 40; ++k)
  {
    cache.store(k, stepOf(100, triangles, k == 13));
  }
  const double oneStep = 2.0 * sizeof(Vec3) * 100;
  cache.thin(12 * oneStep, 27);
  int kept = 0;
  for (int k = 0; k <= 40; ++k)
  {
    kept += cache.has(k);
  }
  SW_CHECK(cache.bytes() <= 12 * oneStep + 10 * sizeof(std::array<int, 3>),
    "under the limit (" << kept << " steps)");
  SW_CHECK(cache.has(0) && cache.has(40) && cache.has(27) && cache.has(13),
    "0, the newest, the shown and the edited kept");
  cache.thin(0, 27);
  kept = 0;
  for (int k = 0; k <= 40; ++k)
  {
    kept += cache.has(k);
  }
  SW_CHECK(kept == 4, "no memory at all: only those four (" << kept << ")");
}
} // namespace

int TestStepCache(int, char*[])
{
  lookups();
  thinning();
  return testing::finish("TestStepCache");
}
