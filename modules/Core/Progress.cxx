#include "Progress.h"

#include <algorithm>
#include <cmath>

namespace art
{
void Progress::Begin(const std::string& stage, double total, double lo, double hi)
{
  {
    std::lock_guard<std::mutex> g(Lock);
    Stage = stage;
    Total = std::max(total, 1e-300);
    Lo = lo;
    Hi = hi;
    LastPercent = -1;
  }
  Done = 0.0;
  Emit(Lo);
}

void Progress::Advance(double units)
{
  double cur = Done.load();
  while (!Done.compare_exchange_weak(cur, cur + units))
  {
  }
  const double f = Lo + (Hi - Lo) * std::min(1.0, (cur + units) / Total);
  const int percent = static_cast<int>(std::floor(f * 100.0));
  if (percent != LastPercent) // racy read is fine: Emit re-checks under the lock
  {
    Emit(f);
  }
}

void Progress::End()
{
  Emit(Hi);
}

void Progress::Emit(double f)
{
  std::lock_guard<std::mutex> g(Lock);
  const int percent = static_cast<int>(std::floor(f * 100.0));
  if (percent <= LastPercent && f < Hi)
  {
    return;
  }
  LastPercent = percent;
  if (Report)
  {
    Report(f, Stage);
  }
}
} // namespace art
