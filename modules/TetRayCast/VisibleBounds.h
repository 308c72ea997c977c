// VisibleBounds: the box of the part of a volume or tet mesh that a transfer function (and its
// iso-surfaces) make visible, which the default camera frames: an MRI's head, not the box of
// air around it. Clipping planes are not applied (the clipped view keeps the whole object's frame).
#ifndef art_VisibleBounds_h
#define art_VisibleBounds_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Box3.h"

class vtkImageData;

namespace art
{
class TetMesh;
struct RenderSettings;

/// Voxels whose value the transfer function gives opacity (and a neighbour's too: lone hot voxels
/// are noise), or whose cell an iso-surface crosses; each axis then drops the outermost 0.05% of
/// them, so a few strays do not widen it. An empty box when nothing is visible.
ADAPTIVERTTETRAYCAST_EXPORT Box3 VisibleBounds(vtkImageData* image, const RenderSettings& s);
/// Tets whose values span an opacity, or an iso-value; an empty box when none does.
ADAPTIVERTTETRAYCAST_EXPORT Box3 VisibleBounds(const TetMesh& mesh, const RenderSettings& s);
} // namespace art

#endif
