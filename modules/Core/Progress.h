// Progress: a thread-safe work counter that reports a fraction in [0, 1] to one callback, at most
// about once per percent, from whichever thread crosses the step (the callback is serialised).
// Also carries a cancel flag so a viewer can abort a long reduction or render.
#ifndef art_Progress_h
#define art_Progress_h

#include "AdaptiveRTCoreModule.h"

#include <atomic>
#include <functional>
#include <mutex>
#include <string>

namespace art
{
class ADAPTIVERTCORE_EXPORT Progress
{
public:
  using Callback = std::function<void(double fraction, const std::string& stage)>;

  Progress() = default;
  explicit Progress(Callback cb) : Report(std::move(cb)) {}

  /// Starts a stage of `total` work units, mapped onto [lo, hi] of the overall fraction.
  void Begin(const std::string& stage, double total, double lo = 0.0, double hi = 1.0);
  void Advance(double units);
  void End();
  void Cancel() { CancelFlag = true; }
  bool Cancelled() const { return CancelFlag; }

private:
  void Emit(double f);

  Callback Report;
  std::mutex Lock;
  std::string Stage;
  std::atomic<double> Done{ 0.0 };
  double Total = 1.0, Lo = 0.0, Hi = 1.0;
  int LastPercent = -1;
  std::atomic<bool> CancelFlag{ false };
};
} // namespace art

#endif
