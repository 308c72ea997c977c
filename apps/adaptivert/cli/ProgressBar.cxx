#include "cli/ProgressBar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace cli
{
ProgressBar::ProgressBar(bool quiet)
  : Quiet(quiet)
  , Tty(isatty(fileno(stderr)) != 0)
  , Start(std::chrono::steady_clock::now())
  , LastDraw(Start)
{
}

ProgressBar::~ProgressBar()
{
  Finish();
}

art::Progress::Callback ProgressBar::Callback()
{
  return [this](double f, const std::string& stage) { Update(f, stage); };
}

void ProgressBar::Update(double f, const std::string& stage)
{
  f = std::clamp(f, 0.0, 1.0);
  const auto now = std::chrono::steady_clock::now();
  const double secs = std::chrono::duration<double>(now - Start).count();
  if (Quiet)
  {
    // Quiet, but not silent for ever: a long job says it is alive once a minute.
    if (now - LastDraw >= HeartbeatPeriod && now - Start >= HeartbeatPeriod)
    {
      LastDraw = now;
      std::fprintf(stderr, "%s: %d%% (%.0f s)\n", stage.c_str(), static_cast<int>(f * 100.0), secs);
      std::fflush(stderr);
    }
    return;
  }
  if (Tty)
  {
    // Redraw at most 20 times a second, but always at the end of a stage.
    if (stage == LastStage && f < 1.0 && now - LastDraw < std::chrono::milliseconds(50))
    {
      return;
    }
    LastDraw = now;
    LastStage = stage;
    const int width = 30, filled = static_cast<int>(f * width + 0.5);
    std::fprintf(stderr, "\r\033[K%-12s [%s%s] %3d%% %6.1f s", stage.c_str(),
      std::string(filled, '#').c_str(), std::string(width - filled, ' ').c_str(),
      static_cast<int>(f * 100.0 + 0.5), secs);
    Open = true;
  }
  else
  {
    const int tenth = static_cast<int>(f * 10.0);
    if (stage != LastStage || tenth > LastTenth)
    {
      std::fprintf(stderr, "%s: %d%% (%.1f s)\n", stage.c_str(), tenth * 10, secs);
      LastStage = stage;
      LastTenth = tenth;
    }
    if (stage != LastStage)
    {
      LastTenth = -1;
    }
  }
  std::fflush(stderr);
}

void ProgressBar::Finish()
{
  if (Open)
  {
    std::fprintf(stderr, "\n");
    Open = false;
  }
}
} // namespace cli
