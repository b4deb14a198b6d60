// Parallel loops through vtkSMPTools that let exceptions out. An exception thrown in a worker thread
// (an allocation failing under a process memory limit, say) would end the process; here the first one
// is kept, the chunks not yet started are skipped, and it is rethrown on the calling thread after the
// loop, where the filter reports it.
#ifndef ShrinkWrap_Parallel_h
#define ShrinkWrap_Parallel_h

#include <vtkSMPTools.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <utility>

namespace shrinkwrap
{

// body(b, e) over chunks [b, e) of [first, last); grain 0 lets vtkSMPTools choose the chunk size.
template <typename Body>
void parallelFor(vtkIdType first, vtkIdType last, vtkIdType grain, Body&& body)
{
  std::exception_ptr failure;
  std::mutex guard;
  std::atomic<bool> failed{ false };
  vtkSMPTools::For(first, last, grain, [&](vtkIdType b, vtkIdType e) {
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

template <typename Body>
void parallelFor(vtkIdType first, vtkIdType last, Body&& body)
{
  parallelFor(first, last, 0, std::forward<Body>(body));
}

} // namespace shrinkwrap

#endif
