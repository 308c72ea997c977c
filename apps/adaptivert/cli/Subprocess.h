// Subprocess: runs a program (no shell, so no quoting issues) and captures its stdout; its
// stderr goes to a log file, or stays the caller's when the log path is empty. `batch` runs each
// frame this way so one failing frame cannot take the batch down; a child dies with its parent
// (PR_SET_PDEATHSIG), so a killed batch leaves no render running.
#ifndef adaptivert_Subprocess_h
#define adaptivert_Subprocess_h

#include <string>
#include <vector>

namespace cli
{
struct SubprocessResult
{
  int exitCode = -1; ///< -1 when it could not start, 128 + signal when killed
  std::string out;
};

SubprocessResult RunProgram(const std::vector<std::string>& argv, const std::string& stderrLog);
/// The path of the running executable (to re-run adaptivert itself).
std::string SelfExecutable();
} // namespace cli

#endif
