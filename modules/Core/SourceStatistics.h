// SourceStatistics: a volume's ScalarStatistics carried in a data set's field data, so that a
// mesh reduced from the volume gets the transfer function the volume itself would get (a
// reduced mesh's vertices crowd at edges and its fitted values overshoot; neither says where the
// volume's background or window lay). The reducer writes them beside scalar_range_min/max:
//   source_window          2 values: the robust window (1st and 99.5th percentiles)
//   source_background_top  1 value, when the volume has a background
//   source_label_values    the label values, when the volume is a label map
#ifndef art_SourceStatistics_h
#define art_SourceStatistics_h

#include "AdaptiveRTCoreModule.h"
#include "ScalarStatistics.h"

#include <functional>

class vtkDataArray;
class vtkFieldData;

namespace art
{
/// Adds (or replaces) the arrays above and scalar_range_min/max in `fd`.
ADAPTIVERTCORE_EXPORT void WriteSourceStatistics(vtkFieldData* fd, const ScalarStatistics& s);
/// Reads what WriteSourceStatistics wrote (samples, not recorded, is set to 1); false when `fd`
/// holds no (or a malformed) source_window.
ADAPTIVERTCORE_EXPORT bool ReadSourceStatistics(vtkFieldData* fd, ScalarStatistics& s);
/// Do n values (value(i)) still stand for a source of range [sourceLo, sourceHi]? A
/// least-squares fit overshoots at sharp edges (a 0..255 volume's mesh reached -160..480, its
/// 2nd percentile -22), but at few vertices: 96% of the values (2nd to 98th percentile of up to
/// 65536 evenly spread) lie within the source range widened by a quarter at each end; values a
/// filter rescaled or shifted do not.
ADAPTIVERTCORE_EXPORT bool StillTheSource(
  double sourceLo, double sourceHi, long long n, const std::function<double(long long)>& value);
/// Summarize over a one-component array (component 0 of others); integer types, or floats that
/// are all whole numbers, may be labels.
ADAPTIVERTCORE_EXPORT ScalarStatistics SummarizeArray(vtkDataArray* a);
} // namespace art

#endif
