// ViewerOptions: the command line of adaptivert-view (FILE, --size, --tets, --refinement, --array,
// --tf, --script, --screenshot, --help). Parsing never touches VTK, so usage errors come before any window.
#ifndef art_ViewerOptions_h
#define art_ViewerOptions_h

#include <stdexcept>
#include "DataLoader.h"

#include <string>
#include <vector>

namespace view
{
/// A mistake on the command line: main prints it in one line and exits 2.
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct ViewerOptions
{
  std::string File;
  int Width = 800, Height = 600;
  std::vector<long long> Tets;   ///< nested reduction budgets, ascending (volumes)
  std::vector<double> TetPercents; ///< more budgets as percentages of the voxel count
  bool TetsGiven = false;         ///< --tets was given (it applies to volumes only)
  std::string Refinement = "bisection"; ///< how the levels are made: bisection, edge or anisotropic
  std::string Array;             ///< point (or cell) array to show (default: the active scalars)
  art::LoadOptions Load;         ///< --frame and a raw volume's --raw-* layout (Array is set on use)
  std::string TransferFunction = "auto";
  bool TfGiven = false;           ///< --tf was given (it applies to volumes and meshes only)
  std::string LabelColours = "values"; ///< --label-colours: a label mesh's values, flat or off
  std::string Script;            ///< file of scripted actions (tests, demos)
  std::string Screenshot;        ///< take one after the script (or the reduction) and exit
  bool Help = false;
};

/// Throws UsageError for unknown options, missing values, bad sizes or budgets.
ViewerOptions ParseOptions(const std::vector<std::string>& args);
/// Tets and TetPercents of `voxels` as one ascending list of budgets; throws UsageError for a
/// percentage under 6 tets.
std::vector<long long> Budgets(const ViewerOptions& o, long long voxels);
std::string UsageText();
} // namespace view

#endif
