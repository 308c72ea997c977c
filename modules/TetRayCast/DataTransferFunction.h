// DataTransferFunction: the default ("auto") transfer function of a volume that is not CT, made
// from its samples as ParaView's and 3D Slicer's automatic presets start: the background (an
// MRI's zero, the air around a scan) transparent, a grey ramp whose opacity rises over the
// robust window (1st to 99.5th percentile of the rest), so that neither the background's noise
// nor a few bright outliers decide the picture; a label map in categorical colours. Under
// maximum intensity, a window that shows the window's top as white.
// A mesh reduced from a volume carries the volume's statistics (SourceStatistics), so both get
// the same function.
#ifndef art_DataTransferFunction_h
#define art_DataTransferFunction_h

#include "AdaptiveRTTetRayCastModule.h"
#include "ScalarStatistics.h"
#include "TransferFunction.h"

class vtkDataSet;

namespace art
{
class TetMesh;

enum class TransferFunctionUse
{
  EmissionAbsorption,
  MaximumIntensity
};

/// Opacity at the window's top per unit distance (emission-absorption), and of each label.
constexpr double DataRampOpacity = 0.2;
constexpr double LabelOpacity = 0.5;

/// The function for samples summarised by `s`, opacities per `unitDistance`.
ADAPTIVERTTETRAYCAST_EXPORT TransferFunction DataTransferFunction(
  const ScalarStatistics& s, double unitDistance, TransferFunctionUse use = TransferFunctionUse::EmissionAbsorption);

/// The statistics that decide it for values in [lo, hi] drawn from `data` (and `mesh`, built from
/// it): the source statistics a reduced mesh records, while its range is still the reduction's;
/// else those of the data's active point scalars when they span [lo, hi] (a volume's voxels), or
/// of the mesh's values; else [lo, hi] as the window, without background.
ADAPTIVERTTETRAYCAST_EXPORT ScalarStatistics StatisticsFor(
  vtkDataSet* data, double lo, double hi, const TetMesh* mesh = nullptr);
} // namespace art

#endif
