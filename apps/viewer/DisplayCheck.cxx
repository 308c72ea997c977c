#include "DisplayCheck.h"

#ifdef ART_HAVE_X11
#include <X11/Xlib.h>
#endif

namespace view
{
std::shared_ptr<void> OpenDisplay()
{
#ifdef ART_HAVE_X11
  Display* d = XOpenDisplay(nullptr);
  if (!d)
  {
    return nullptr;
  }
  return std::shared_ptr<void>(d, [](void* p) { XCloseDisplay(static_cast<Display*>(p)); });
#else
  static int dummy;
  return std::shared_ptr<void>(&dummy, [](void*) {});
#endif
}

bool IsXDisplay(const std::shared_ptr<void>&)
{
#ifdef ART_HAVE_X11
  return true;
#else
  return false;
#endif
}
} // namespace view
