// The core's one seam to threads: parallel loops over index ranges, per-thread scratch, and the
// scope that gives a computation all cores. Behind it is vtkSMPTools (Parallel.cxx, the only file
// of the core that sees VTK). An exception thrown in a worker (an allocation failing under a
// process memory limit, say) is kept, the chunks not yet started are skipped, and it is rethrown on
// the calling thread after the loop.
#ifndef ShrinkWrap_Parallel_h
#define ShrinkWrap_Parallel_h

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace shrinkwrap
{

using Index = std::int64_t; // a loop index: vertices, triangles, grid nodes

// Items of a few dozen operations each (a vertex's or a triangle's geometry) pay for threads only
// from about this many per chunk: the thread backend starts a loop's threads anew each time.
constexpr Index kCheapGrain = 16384;
// Items of a grid query and a few exact tests each (a triangle against its neighbours).
constexpr Index kQueryGrain = 512;

// A reference to a callable, cheap to pass through the seam (the callable must outlive the call).
class ChunkBody
{
public:
  template <typename F, typename = std::enable_if_t<!std::is_same_v<std::decay_t<F>, ChunkBody>>>
  ChunkBody(F& f) // NOLINT: implicit, as a function argument
    : Object(const_cast<void*>(static_cast<const void*>(&f)))
    , Call([](void* o, Index b, Index e) { (*static_cast<F*>(o))(b, e); })
  {
  }
  void operator()(Index b, Index e) const { this->Call(this->Object, b, e); }

private:
  void* Object;
  void (*Call)(void*, Index, Index);
};

// body(b, e) over chunks [b, e) of [first, last); grain 0 lets the backend choose the chunk size,
// and a grain of at least last - first runs body on the calling thread.
void parallelForChunks(Index first, Index last, Index grain, ChunkBody body);

template <typename Body>
void parallelFor(Index first, Index last, Index grain, Body&& body)
{
  parallelForChunks(first, last, grain, ChunkBody(body));
}

template <typename Body>
void parallelFor(Index first, Index last, Body&& body)
{
  parallelForChunks(first, last, 0, ChunkBody(body));
}

// Runs f with all cores available to the parallel loops inside it (a scoped thread backend, which
// leaves the process-wide choice alone; a backend chosen through VTK_SMP_BACKEND_IN_USE wins).
void onAllCores(const std::function<void()>& f);

// One T per thread that asks for it, made by `make` on first use; visited after the loop.
template <typename T>
class ThreadLocal
{
public:
  explicit ThreadLocal(std::function<T()> make = [] { return T(); })
    : Make(std::move(make))
  {
  }
  T& local()
  {
    const std::thread::id me = std::this_thread::get_id();
    const std::lock_guard<std::mutex> lock(this->Guard);
    for (auto& slot : this->Slots)
    {
      if (slot.first == me)
      {
        return *slot.second;
      }
    }
    this->Slots.emplace_back(me, std::make_unique<T>(this->Make()));
    return *this->Slots.back().second;
  }
  // f(T&) for every thread's T, in the order the threads first asked.
  template <typename F>
  void forEach(F&& f)
  {
    for (auto& slot : this->Slots)
    {
      f(*slot.second);
    }
  }

private:
  std::function<T()> Make;
  std::mutex Guard;
  std::vector<std::pair<std::thread::id, std::unique_ptr<T>>> Slots;
};

} // namespace shrinkwrap

#endif
