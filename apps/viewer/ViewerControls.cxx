#include "ViewerControls.h"

#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace view
{
const double* ErtSteps(int* count)
{
  static const double steps[] = { 0.99, 0.95, 0.9, 0.8, 0.5, 1.0 };
  *count = static_cast<int>(sizeof(steps) / sizeof(steps[0]));
  return steps;
}

double ViewerState::Ert() const
{
  int n;
  return ErtSteps(&n)[ErtIndex % n];
}

KeyResult ApplyKey(ViewerState& s, char key, int levels)
{
  switch (key)
  {
    case ']':
    case '[':
    {
      const int to = s.Level + (key == ']' ? 1 : -1);
      if (levels == 0 || to < 0 || to >= levels)
      {
        return KeyResult::Ignored;
      }
      s.Level = to;
      s.FollowNewest = false;
      return KeyResult::LevelChanged;
    }
    case 'i':
      s.Iso = !s.Iso;
      return KeyResult::Changed;
    case '+':
    case '=':
      s.IsoValue = std::min(s.IsoValue + s.IsoStep, s.IsoHi);
      s.Iso = true;
      return KeyResult::Changed;
    case '-':
      s.IsoValue = std::max(s.IsoValue - s.IsoStep, s.IsoLo);
      s.Iso = true;
      return KeyResult::Changed;
    case 't':
    {
      int n;
      ErtSteps(&n);
      s.ErtIndex = (s.ErtIndex + 1) % n;
      return KeyResult::Changed;
    }
    case 'x':
      s.Trapezoid = !s.Trapezoid;
      return KeyResult::Changed;
    case 'l':
      s.Shade = !s.Shade;
      return KeyResult::Changed;
    case 'm':
      s.Edges = !s.Edges;
      return KeyResult::Changed;
    case 'c':
      s.Clip = !s.Clip;
      return KeyResult::Changed;
    case 'h':
      s.Help = !s.Help;
      return KeyResult::Changed;
    case 's':
      return KeyResult::Screenshot;
    case 'r':
      return KeyResult::ResetCamera;
    case 'q':
    case 'e':
    case 27:
      return KeyResult::Quit;
    default:
      if (key >= '1' && key <= '9' && key - '1' < levels)
      {
        s.Level = key - '1';
        s.FollowNewest = false;
        return KeyResult::LevelChanged;
      }
      return KeyResult::Ignored;
  }
}

std::string ReducedText(int levels)
{
  return "reduced: " + std::to_string(levels) + (levels == 1 ? " level" : " levels") + " from one run";
}

std::string HelpText(const ViewerState& s, bool volume)
{
  std::ostringstream os;
  char iso[64];
  std::snprintf(iso, sizeof iso, "%s at %g", s.Iso ? "on" : "off", s.IsoValue);
  if (volume)
  {
    os << "[ ] 1-9  tet level\n";
    os << "i + -    iso-surface: " << iso << "\n";
    os << "t        early termination: " << (s.Ert() >= 1.0 ? std::string("off") : std::to_string(s.Ert()).substr(0, 4))
       << "\n";
    os << "x        integrator: " << (s.Trapezoid ? "trapezoid" : "exact") << "\n";
    os << "l        lighting (shade): " << (s.Shade ? "on" : "off") << "\n";
    os << "m        mesh edges: " << (s.Edges ? "on" : "off") << "\n";
    os << "c        clipping plane: " << (s.Clip ? "on (drag it)" : "off") << "\n";
  }
  os << "s        screenshot\n";
  os << "r        reset camera\n";
  os << "h        hide help   q quit\n";
  os << "mouse    rotate, pan, zoom";
  return os.str();
}
} // namespace view

vtkStandardNewMacro(vtkViewerInteractorStyle);

void vtkViewerInteractorStyle::OnChar()
{
  vtkRenderWindowInteractor* rwi = this->Interactor;
  if (!rwi || !this->KeyHandler)
  {
    return;
  }
  char key = rwi->GetKeyCode();
  const char* sym = rwi->GetKeySym();
  if (key == 0 && sym && std::string(sym) == "Escape")
  {
    key = 27;
  }
  this->KeyHandler(key);
}
