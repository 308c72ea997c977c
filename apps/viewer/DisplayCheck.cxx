#include "DisplayCheck.h"

#ifdef ART_HAVE_X11
#include <X11/Xlib.h>
#endif

namespace view
{
bool CanOpenDisplay()
{
#ifdef ART_HAVE_X11
  Display* d = XOpenDisplay(nullptr);
  if (!d)
  {
    return false;
  }
  XCloseDisplay(d);
#endif
  return true;
}
} // namespace view
