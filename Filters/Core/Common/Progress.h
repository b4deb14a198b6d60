// Progress and abort for long loops, without VTK in the interface. The callback runs on the calling
// thread, between parallel chunks, and returns false to stop the work.
#ifndef ShrinkWrap_Progress_h
#define ShrinkWrap_Progress_h

#include <algorithm>
#include <chrono>
#include <functional>

namespace shrinkwrap
{

class Progress
{
public:
  using Callback = std::function<bool(double)>;

  Progress() = default;
  explicit Progress(Callback callback, double begin = 0, double end = 1)
    : Report(std::move(callback))
    , Begin(begin)
    , End(end)
  {
  }

  // fraction in [0, 1] of this stage; false when the user asked to stop.
  bool report(double fraction) const
  {
    return !this->Report ||
      this->Report(this->Begin + std::clamp(fraction, 0.0, 1.0) * (this->End - this->Begin));
  }

  // The part [begin, end] of this stage, as a stage of its own.
  Progress stage(double begin, double end) const
  {
    const double w = this->End - this->Begin;
    return Progress(this->Report, this->Begin + begin * w, this->Begin + end * w);
  }

private:
  Callback Report;
  double Begin = 0;
  double End = 1;
};

// A stop request asked from within a long serial loop (the edits of a remeshing pass, say): called
// per item, it asks `stop` (empty: never) on the kCallsPerClock-th call and then at most every
// kPollSeconds, reading the clock every kCallsPerClock calls, and stays true once `stop` said so.
// `stop` must outlive it.
class StopPoll
{
public:
  static constexpr double kPollSeconds = 0.1;
  static constexpr int kCallsPerClock = 8;
  explicit StopPoll(const std::function<bool()>& stop)
    : Stop(stop)
  {
  }
  bool operator()()
  {
    if (this->Stopped || !this->Stop || ++this->Calls % kCallsPerClock != 0)
    {
      return this->Stopped;
    }
    return this->now();
  }
  // Asks `stop` now if it was not asked in the last kPollSeconds (between the phases of one long
  // item, say).
  bool now()
  {
    if (this->Stopped || !this->Stop)
    {
      return this->Stopped;
    }
    const auto at = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(at - this->Last).count() < kPollSeconds)
    {
      return false;
    }
    this->Last = at;
    return this->Stopped = this->Stop();
  }

private:
  const std::function<bool()>& Stop;
  std::chrono::steady_clock::time_point Last; // none yet: the first clock reading asks
  long long Calls = 0;
  bool Stopped = false;
};

// Runs body(first, last) over [0, n) in `chunks` parallel batches, reporting after each batch.
// Returns false if aborted.
template <typename Body>
bool forChunks(long long n, int chunks, const Progress& progress, Body&& body);

} // namespace shrinkwrap

#include "Common/Parallel.h"

template <typename Body>
bool shrinkwrap::forChunks(long long n, int chunks, const Progress& progress, Body&& body)
{
  chunks = static_cast<int>(std::max<long long>(1, std::min<long long>(chunks, n)));
  for (int c = 0; c < chunks; ++c)
  {
    const long long first = n * c / chunks, last = n * (c + 1) / chunks;
    parallelFor(first, last, [&](Index b, Index e) { body(b, e); });
    if (!progress.report(static_cast<double>(c + 1) / chunks))
    {
      return false;
    }
  }
  return true;
}

#endif
