#include "Common/Parallel.h"

#include <vtkSMPTools.h>

#include <atomic>
#include <cstdlib>
#include <exception>

namespace shrinkwrap
{

void parallelForChunks(Index first, Index last, Index grain, ChunkBody body)
{
  std::exception_ptr failure;
  std::mutex guard;
  std::atomic<bool> failed{ false };
  vtkSMPTools::For(first, last, grain, [&](Index b, Index e) {
    if (failed.load(std::memory_order_relaxed))
    {
      return;
    }
    try
    {
      body(b, e);
    }
    catch (...)
    {
      const std::lock_guard<std::mutex> lock(guard);
      if (!failure)
      {
        failure = std::current_exception();
      }
      failed = true;
    }
  });
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

void onAllCores(const std::function<void()>& f)
{
  if (std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    f();
    return;
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, f);
}

} // namespace shrinkwrap
