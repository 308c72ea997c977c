// DisplayCheck: opens the X display in $DISPLAY for the viewer's window. VTK's X render window
// crashes on a display it cannot open, so the viewer opens it first, refuses in one line when
// that fails, and hands the open connection to VTK. Kept apart because Xlib's macros (Status,
// None, Bool) clash with ordinary names.
#ifndef art_DisplayCheck_h
#define art_DisplayCheck_h

#include <memory>

namespace view
{
/// The open connection (an X Display*, closed when the last owner lets go), or null when
/// $DISPLAY cannot be opened. Without Xlib headers at build time: a non-null dummy.
std::shared_ptr<void> OpenDisplay();
/// True when `d` is a real X connection that VTK can be given.
bool IsXDisplay(const std::shared_ptr<void>& d);
} // namespace view

#endif
