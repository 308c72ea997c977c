// ViewerScript: scripted actions for tests and demos, one per line ('#' comments):
//   key K            press key K (the same handler as the keyboard: ] [ 1-9 i + - t x m h s r)
//   wait S           wait S seconds
//   wait-reduction   wait until the background reduction has finished
//   azimuth DEG | elevation DEG | roll DEG | zoom F     move the camera
//   drag DX DY       drag with the left mouse button from the window's centre (the trackball)
//   screenshot FILE  save the window as a PNG
// The viewer steps it from its repeating timer, so the window stays live while it runs.
#ifndef art_ViewerScript_h
#define art_ViewerScript_h

#include <string>
#include <vector>

namespace view
{
struct ScriptAction
{
  enum class Kind
  {
    Key,
    Wait,
    WaitReduction,
    Azimuth,
    Elevation,
    Roll,
    Zoom,
    Drag,
    Screenshot
  };
  Kind What = Kind::Key;
  std::string Text; ///< the key, or the screenshot file
  double Value = 0; ///< seconds, degrees, zoom factor or DX
  double Value2 = 0; ///< DY of a drag
  int Line = 0;
};

/// Reads a script; throws art::Error naming the file and line for anything malformed.
std::vector<ScriptAction> ReadScript(const std::string& path);
} // namespace view

#endif
