// DisplayCheck: whether the X display in $DISPLAY can be opened. VTK's X render window crashes
// on one it cannot open, so the viewer asks first and refuses in one line. Kept apart because
// Xlib's macros (Status, None, Bool) clash with ordinary names.
#ifndef art_DisplayCheck_h
#define art_DisplayCheck_h

namespace view
{
/// True when $DISPLAY opens (always true when built without Xlib headers).
bool CanOpenDisplay();
} // namespace view

#endif
