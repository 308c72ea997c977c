// BatchJob: a JSON job file of data sets x cameras x settings, expanded into render tasks.
// Settings are render options by name ({"tets": 20000, "integrator": "exact"} becomes
// `--tets 20000 --integrator exact`), so the job file speaks the CLI's own language and a
// misspelt option fails the same way on the command line.
#ifndef adaptivert_BatchJob_h
#define adaptivert_BatchJob_h

#include <string>
#include <vector>

namespace cli
{
struct BatchTask
{
  std::string name;      ///< unique file stem, e.g. "ct-head-128_c03_s01"
  std::string dataset;   ///< input path
  std::string setting;   ///< the setting as text, for the CSV ("tets=20000 integrator=exact")
  std::vector<std::string> args; ///< render arguments after INPUT
  std::string reference; ///< name of the reference task this is compared with ("" = none)
  bool isReference = false;
  int camera = 0;
};

struct BatchJob
{
  std::string file;      ///< the job file
  std::string outputDir; ///< absolute
  std::vector<BatchTask> tasks; ///< references first, so others can compare as soon as possible
  /// Settings whose picture differs from the reference's (their own tf, clip, iso, ...): their
  /// error is against another picture. One line each, for the batch to say before it renders.
  std::vector<std::string> notes;
};

/// Parses and expands a job file; throws art::Error naming the file and the problem (an unknown
/// key too: keys starting with '_' are free for comments).
///
/// {
///   "output": "frames",                       folder for images and results (relative to the job file)
///   "datasets": ["../data/ct-head-128.mha"],  relative to the job file
///   "size": "400x400",
///   "cameras": {"orbit": 8, "elevation": 15, "zoom": 1.0}   N frames around the data
///           or [{"azimuth": 0, "elevation": 10}, ...],
///   "settings": [{"tets": 20000}, {"tets": 80000, "integrator": "trapezoid"}],
///                                             a file a setting names ("tf": "bone.tf") is
///                                             relative to the job file too
///   "reference": {"reference": true}          render options of the reference image per camera
///                                             (optional; without it no error is computed)
/// }
BatchJob LoadBatchJob(const std::string& path);
} // namespace cli

#endif
