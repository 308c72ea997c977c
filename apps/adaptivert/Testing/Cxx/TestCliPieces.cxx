// The CLI's own pieces without a command around them: option suggestions and the progress bar.
#include "cli/Options.h"
#include "cli/ProgressBar.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace
{
cli::Options RenderLike()
{
  cli::Options o;
  o.Add("tets", 0, "N", "");
  o.Add("max-error", 0, "E", "");
  o.Add("tf", 0, "NAME", "");
  o.Add("azimuth", 0, "DEG", "");
  return o;
}
} // namespace

TEST(Options, SuggestsTheNearestDeclaredName)
{
  const cli::Options o = RenderLike();
  EXPECT_EQ(o.Suggest("tet"), "tets");          // cut short
  EXPECT_EQ(o.Suggest("max-eror"), "max-error"); // a letter missing
  EXPECT_EQ(o.Suggest("azimtuh"), "azimuth");    // two swapped
  EXPECT_EQ(o.Suggest("bogus"), "");             // nothing near
  EXPECT_EQ(o.Suggest("t"), "tf");               // short names only one edit away
  EXPECT_EQ(o.Suggest("x"), "");
}

TEST(Options, UnknownOptionNamesTheSuggestion)
{
  cli::Options o = RenderLike();
  const char* argv[] = { "render", "--tet", "100" };
  try
  {
    o.Parse(3, const_cast<char**>(argv), 1);
    FAIL() << "--tet was accepted";
  }
  catch (const cli::UsageError& e)
  {
    EXPECT_STREQ(e.what(), "unknown option '--tet' (did you mean --tets?)");
  }
}

// Quiet means no bar, but a job running past the heartbeat period still says it is alive.
TEST(ProgressBar, QuietSaysALongJobIsAlive)
{
  const auto saved = cli::ProgressBar::HeartbeatPeriod;
  cli::ProgressBar::HeartbeatPeriod = std::chrono::milliseconds(100);
  testing::internal::CaptureStderr();
  {
    cli::ProgressBar bar(true);
    bar.Update(0.1, "reduce"); // early: silent
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    bar.Update(0.4, "reduce"); // past the period: one line
    bar.Update(0.5, "reduce"); // within the next period: silent
  }
  const std::string err = testing::internal::GetCapturedStderr();
  cli::ProgressBar::HeartbeatPeriod = saved;
  EXPECT_EQ(err.find("10%"), std::string::npos) << err;
  EXPECT_NE(err.find("reduce: 40%"), std::string::npos) << err;
  EXPECT_EQ(err.find("50%"), std::string::npos) << err;
}

TEST(ProgressBar, QuietShortJobPrintsNothing)
{
  testing::internal::CaptureStderr();
  {
    cli::ProgressBar bar(true);
    bar.Update(0.5, "render");
    bar.Update(1.0, "render");
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}
