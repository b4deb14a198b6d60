// Parallel loops through vtkSMPTools that let exceptions out, and the scope that gives them
// threads. An exception thrown in a worker thread
// (an allocation failing under a process memory limit, say) would end the process; here the first one
// is kept, the chunks not yet started are skipped, and it is rethrown on the calling thread after the
// loop, where the filter reports it.
#ifndef ShrinkWrap_Parallel_h
#define ShrinkWrap_Parallel_h

#include <vtkSMPTools.h>

#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <utility>

namespace shrinkwrap
{

// Items of a few dozen operations each (a vertex's or a triangle's geometry) pay for threads only from
// about this many per chunk: VTK 9.2's STDThread backend starts a loop's threads anew each time (tens of
// microseconds each on a virtual machine), so a loop over a few thousand of them is faster on one.
constexpr vtkIdType kCheapGrain = 16384;
// Items of a grid query and a few exact tests each (a triangle against its neighbours): chunks of 512 put
// a fine wrap's checks of changed triangles on both cores (the camel's at Resolution 200: 0.90 -> 0.53 s).
constexpr vtkIdType kQueryGrain = 512;

// body(b, e) over chunks [b, e) of [first, last); grain 0 lets vtkSMPTools choose the chunk size, and
// a grain of at least last - first runs body on the calling thread.
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

// Runs f with vtkSMPTools on all cores. Debian's VTK defaults to the Sequential backend, so the work
// runs under a scoped STDThread backend, which leaves the process-wide choice alone; a backend the
// user chose through VTK_SMP_BACKEND_IN_USE wins.
template <typename F>
void onAllCores(F&& f)
{
  if (std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    f();
    return;
  }
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, f);
}

} // namespace shrinkwrap

#endif
