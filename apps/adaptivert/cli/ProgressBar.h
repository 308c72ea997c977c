// ProgressBar: progress on stderr. On a terminal a bar redrawn in place; otherwise one plain
// line per stage and per 10%, so logs stay readable. Quiet (-q): nothing, unless the job runs
// past a minute, then one line a minute. Feeds from art::Progress callbacks.
#ifndef adaptivert_ProgressBar_h
#define adaptivert_ProgressBar_h

#include "Progress.h"

#include <chrono>
#include <string>

namespace cli
{
class ProgressBar
{
public:
  explicit ProgressBar(bool quiet = false);
  /// How often a quiet bar says a long job is alive (a test shortens it).
  static inline std::chrono::steady_clock::duration HeartbeatPeriod = std::chrono::minutes(1);
  ~ProgressBar();
  /// A callback for art::Progress.
  art::Progress::Callback Callback();
  void Update(double fraction, const std::string& stage);
  void Finish();

private:
  bool Quiet, Tty, Open = false;
  std::string LastStage;
  int LastTenth = -1;
  std::chrono::steady_clock::time_point Start, LastDraw;
};
} // namespace cli

#endif
