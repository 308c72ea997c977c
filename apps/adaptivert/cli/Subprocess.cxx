#include "cli/Subprocess.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

#include <climits>

namespace cli
{
std::string SelfExecutable()
{
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, static_cast<size_t>(n)) : std::string("adaptivert");
}

SubprocessResult RunProgram(const std::vector<std::string>& argv, const std::string& stderrLog)
{
  SubprocessResult r;
  int pipefd[2];
  if (argv.empty() || pipe(pipefd) != 0)
  {
    return r;
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0)
  {
    close(pipefd[0]);
    close(pipefd[1]);
    return r;
  }
  if (pid == 0)
  {
    // A killed batch takes its frame with it: the child is killed when its parent dies (a
    // SIGKILL of `adaptivert batch` left its render running), and exits at once if that
    // happened before this line.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent)
    {
      _exit(128 + SIGKILL);
    }
    dup2(pipefd[1], STDOUT_FILENO);
    close(pipefd[0]);
    close(pipefd[1]);
    const int err = stderrLog.empty() ? -1 : open(stderrLog.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err >= 0)
    {
      dup2(err, STDERR_FILENO);
      close(err);
    }
    std::vector<char*> args;
    for (const auto& a : argv)
    {
      args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  close(pipefd[1]);
  char buf[4096];
  ssize_t n;
  while ((n = read(pipefd[0], buf, sizeof buf)) > 0)
  {
    r.out.append(buf, static_cast<size_t>(n));
  }
  close(pipefd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}
} // namespace cli
