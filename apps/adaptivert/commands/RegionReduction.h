// RegionReduction: `adaptivert reduce IN OUT.vtu --region LO:HI` and `--labels`: tets only where
// the object is (art::ReduceRegion, meshed by CGAL's Mesh_3 when AdaptiveRT::Meshing is in the
// build), and, for a region, the tets a whole-box reduction of equal error inside it needs.
#ifndef adaptivert_RegionReduction_h
#define adaptivert_RegionReduction_h

#include "cli/Options.h"

#include <string>

class vtkImageData;

namespace cli
{
/// Declares --region, --labels, --background, --min-island and --no-whole-box.
void DeclareRegionOptions(Options& o);
/// True when `o` asks for a region or label reduction; usage errors for options that do not
/// go with one (checked before anything is read).
bool WantsRegion(const Options& o);
/// Reduces `image` (loaded from `in`) to `out`; returns the exit code.
int RunRegionReduction(const Options& o, const std::string& in, const std::string& out, vtkImageData* image);
} // namespace cli

#endif
