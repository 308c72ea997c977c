// TransferFunction: scalar -> colour and extinction, piecewise linear between the union of the
// control points of a vtkVolumeProperty's colour and scalar-opacity functions (the emission-
// absorption model of Max 1995, as VTK's volume mappers use it).
//
// Opacity to extinction: VTK's scalar opacity alpha is the opacity of a slab ScalarOpacityUnitDistance
// (u) thick, so the extinction coefficient is tau = -ln(1 - alpha) / u (per world unit). We convert at
// every control point and keep tau (not alpha) linear between them, which is what makes the exact
// segment rule closed-form; alpha = 1 is clamped to 1 - 1e-6. Where VTK's functions are not linear
// between their nodes (a colour space other than RGB, midpoints, sharpness, a log scale) FromVTK
// adds nodes until linear pieces follow them to 1/500; outside the nodes values clamp.
#ifndef art_TransferFunction_h
#define art_TransferFunction_h

#include "AdaptiveRTTetRayCastModule.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

class vtkDataSet;
class vtkVolumeProperty;

#if defined(__GNUC__)
#define ART_TF_INLINE __attribute__((always_inline))
#else
#define ART_TF_INLINE
#endif

namespace art
{
class TetMesh;
class ADAPTIVERTTETRAYCAST_EXPORT TransferFunction
{
public:
  struct Node
  {
    double s;      ///< scalar value
    double rgb[3]; ///< colour in [0, 1]
    double alpha;  ///< opacity per unit distance, as VTK states it
    double tau;    ///< extinction per world unit
  };

  TransferFunction() = default;
  /// Nodes in any order; duplicates at one scalar keep the last. Throws art::Error when empty.
  TransferFunction(std::vector<Node> nodes, double unitDistance = 1.0);

  /// The colour, scalar-opacity functions and unit distance of `p` (component 0).
  static TransferFunction FromVTK(vtkVolumeProperty* p);
  /// "ct-skin-bone", "ct-bone", "grey-ramp", "constant", "labels" (one colour per integer) laid over the data range [lo, hi]
  /// (CT presets use Hounsfield units when the range looks like CT, else fractions of it), their
  /// opacities per unitDistance world units (PresetUnitDistance gives the data's). "auto" is
  /// ct-skin-bone when the range looks like CT, else grey-ramp (PresetFor looks at the samples).
  static TransferFunction Preset(const std::string& name, double lo, double hi, double unitDistance = 1.0);
  static std::vector<std::string> PresetNames();
  /// The k-th colour (k >= 0, cycling) of the ten of Tableau's categorical palette, as ParaView's
  /// categorical presets start: neighbouring labels stay apart.
  static const double* CategoricalColour(long long k);
  /// Does the range [lo, hi] look like CT in Hounsfield units (air near -1000, bone above 500)?
  static bool LooksLikeHU(double lo, double hi) { return lo <= -500.0 && hi >= 500.0; }
  /// The unit distance a preset gets over data with scalar range [lo, hi] and mean sample spacing
  /// h: 1 for CT in Hounsfield units with voxels of 0.1 to 10 (millimetres, as clinical and most
  /// industrial CT store them; the CT presets' opacities are per millimetre), else h, so that the
  /// same samples render alike in metres, millimetres or microns (ParaView likewise scales its
  /// unit distance to the data): a CT in metres or a micro-CT of 20-micron voxels would otherwise
  /// be all but clear, and one in centimetres too thick to see into.
  static double PresetUnitDistance(double lo, double hi, double h);
  /// Mean sample spacing of a data set: an image's geometric mean spacing over its axes of more
  /// than one sample; for other data the field "source_spacing" (which the reducer writes, so a
  /// reduced mesh renders as its volume did), else art::MeanSpacing of the bounds and number of
  /// the points of `mesh` when given (TetMesh::FromVTK merges duplicate points and leaves out
  /// those no cell uses, so the same cells get the same spacing however their points are
  /// stored), else of the data set's own.
  static double SampleSpacing(vtkDataSet* data, const TetMesh* mesh = nullptr);
  /// Preset with the unit distance PresetUnitDistance gives for `data` (built into `mesh`) and its range [lo, hi].
  /// A range that looks like CT counts as CT only when the samples drawn (the mesh's, or the
  /// data's active point scalars) are whole numbers or hold air (5% within 100 of -1000): a
  /// simulation field spanning -1000 .. 1000 gets the grey ramp and fractions of its range.
  /// "auto" on data that is not CT is DataTransferFunction of its statistics (StatisticsFor).
  static TransferFunction PresetFor(const std::string& name, vtkDataSet* data, double lo, double hi,
    const TetMesh* mesh = nullptr);
  /// The default under maximum intensity (CT included): white, its opacity linear over the robust
  /// window of StatisticsFor(data, lo, hi, mesh), so the pixels span black to white.
  static TransferFunction MaximumIntensityFor(vtkDataSet* data, double lo, double hi, const TetMesh* mesh = nullptr);
  /// A text file, one node per line: "scalar r g b opacity" ('#' comments; optional first line
  /// "unit-distance U"), or a ParaView preset as its "Export" writes it (JSON: "RGBPoints",
  /// "ColorSpace", "Points" for the opacity, else a ramp from 0 to 1 over the colour points).
  /// Throws art::Error naming the file (and line) for anything malformed.
  static TransferFunction FromFile(const std::string& path);
  /// Does a --tf value name a file (it exists, or has a '.' or '/') rather than a preset?
  static bool NamesFile(const std::string& tf);

  /// Fills a vtkVolumeProperty with the same functions (for VTK's own mappers and the viewer).
  void ToVTK(vtkVolumeProperty* p) const;

  const std::vector<Node>& Nodes() const { return N; }
  /// The opacity function as (scalar, opacity) points: what the reducer weighs a fit by
  /// (art::ReducerOptions::ScalarOpacity).
  std::vector<std::pair<double, double>> OpacityPoints() const
  {
    std::vector<std::pair<double, double>> p;
    for (const Node& n : N)
    {
      p.emplace_back(n.s, n.alpha);
    }
    return p;
  }
  double UnitDistance() const { return Unit; }

  /// Index i of the interval [s_i, s_{i+1}] holding s (-1 below the first node, size-1 above).
  /// Inline: the ray caster asks once or twice per tet.
  ART_TF_INLINE int Locate(double s) const
  {
    if (s < N.front().s)
    {
      return -1;
    }
    const int last = static_cast<int>(N.size()) - 1;
    if (s >= N.back().s)
    {
      return last;
    }
    int i = Table[static_cast<std::size_t>((s - T0) * TScale)];
    while (i < last && N[i + 1].s <= s)
    {
      ++i;
    }
    while (i > 0 && N[i].s > s)
    {
      --i;
    }
    return i;
  }
  /// Locate(s) for s likely in interval i (the last one of a ray): two comparisons when it is,
  /// two more when s lies in a neighbouring interval (a segment that crosses one control point).
  ART_TF_INLINE int LocateFrom(double s, int i) const
  {
    const std::size_t j = static_cast<std::size_t>(i + 1);
    if (s >= Bounds[j].lo)
    {
      if (s < Bounds[j].hi)
      {
        return i;
      }
      if (j + 1 < Bounds.size() && s < Bounds[j + 1].hi)
      {
        return i + 1; // Bounds[j + 1].lo is Bounds[j].hi
      }
    }
    else if (j > 0 && s >= Bounds[j - 1].lo)
    {
      return i - 1;
    }
    return Locate(s);
  }
  /// Colour and extinction at s.
  void Evaluate(double s, double rgb[3], double& tau) const { EvaluateIn(Locate(s), s, rgb, tau); }
  /// The same, with s known to lie in interval i = Locate(s).
  ART_TF_INLINE void EvaluateIn(int i, double s, double rgb[3], double& tau) const
  {
    if (i < 0 || i + 1 >= static_cast<int>(N.size()))
    {
      const Node& n = i < 0 ? N.front() : N.back();
      rgb[0] = n.rgb[0], rgb[1] = n.rgb[1], rgb[2] = n.rgb[2];
      tau = n.tau;
      return;
    }
    const Node& a = N[i];
    const Slope& d = Slopes[i];
    const double ds = s - a.s;
    rgb[0] = a.rgb[0] + ds * d.rgb[0], rgb[1] = a.rgb[1] + ds * d.rgb[1], rgb[2] = a.rgb[2] + ds * d.rgb[2];
    tau = a.tau + ds * d.tau;
  }
  /// True when the extinction is zero all over the intervals i0 .. i1 (either order; -1 and
  /// size-1 are the clamped ends, as Locate numbers them): a segment whose scalar runs between
  /// them neither absorbs nor emits.
  ART_TF_INLINE bool TransparentIntervals(int i0, int i1) const
  {
    if (i0 > i1)
    {
      std::swap(i0, i1);
    }
    return OpaqueIntervals[i1 + 2] == OpaqueIntervals[i0 + 1];
  }
  /// True when the extinction is zero for every scalar between s0 and s1 (either order), tested
  /// on the Locate table's buckets (conservative at bucket edges). Such a segment neither absorbs
  /// nor emits, and most segments under a typical transfer function are like that.
  bool Transparent(double s0, double s1) const
  {
    int j0 = Bucket(s0), j1 = Bucket(s1);
    if (j0 > j1)
    {
      std::swap(j0, j1);
    }
    return OpaqueBuckets[j1 + 1] == OpaqueBuckets[j0];
  }

  /// Opacity per unit distance at s (for maximum-intensity projection).
  double Alpha(double s) const;

private:
  void BuildTable();
  static TransferFunction ReadFile(const std::string& path); ///< FromFile, errors not yet naming it
  /// Preset, with `hu` saying whether the data are CT in Hounsfield units.
  static TransferFunction Make(const std::string& name, double lo, double hi, double unitDistance, bool hu);

  std::vector<Node> N;
  double Unit = 1.0;
  // Locate in O(1): Table[k] is the interval holding the start of bucket k over [s_0, s_last].
  std::vector<int> Table;
  static constexpr int Buckets = 4096;
  /// 0 below the first node, 1 .. Buckets over the nodes, Buckets + 1 from the last node up.
  int Bucket(double s) const
  {
    if (s < T0)
    {
      return 0;
    }
    if (s >= N.back().s)
    {
      return Buckets + 1;
    }
    return 1 + std::min(static_cast<int>((s - T0) * TScale), Buckets - 1);
  }
  // OpaqueBuckets[j] counts the buckets below bucket j with any extinction.
  std::vector<int> OpaqueBuckets;
  /// Colour and extinction per unit scalar over interval i (EvaluateIn without a division).
  struct Slope
  {
    double rgb[3], tau;
  };
  std::vector<Slope> Slopes;
  /// OpaqueIntervals[j] counts the intervals -1 .. j-2 with extinction at either end.
  std::vector<int> OpaqueIntervals;
  /// The scalars interval j-1 spans (infinite past the end nodes), for LocateFrom.
  struct Span
  {
    double lo, hi;
  };
  std::vector<Span> Bounds;
  double T0 = 0, TScale = 0;
};
} // namespace art

#endif
