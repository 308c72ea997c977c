// FrameClaim: one process at a time renders a frame. A claim is a lock file created with
// O_EXCL holding "host pid"; a claim whose process is gone (same host) is stale and taken over,
// so a killed batch resumes without manual clean-up.
#ifndef adaptivert_FrameClaim_h
#define adaptivert_FrameClaim_h

#include <string>

namespace cli
{
class FrameClaim
{
public:
  /// Tries to claim `lockPath`; Held() says whether it worked.
  explicit FrameClaim(std::string lockPath);
  ~FrameClaim();
  FrameClaim(const FrameClaim&) = delete;
  FrameClaim& operator=(const FrameClaim&) = delete;
  bool Held() const { return Mine; }

private:
  bool TryCreate();
  std::string Path;
  bool Mine = false;
};
} // namespace cli

#endif
