#include "rendering/TransferFunctionChoice.h"

#include "cli/Options.h"

#ifdef ART_HAVE_TetRayCast
#include "TransferFunction.h"
#endif

#include <algorithm>

namespace cli
{
void CheckTransferFunctionName(const std::string& tf)
{
#ifdef ART_HAVE_TetRayCast
  if (art::TransferFunction::NamesFile(tf))
  {
    return;
  }
  const auto names = art::TransferFunction::PresetNames();
  if (std::find(names.begin(), names.end(), tf) != names.end())
  {
    return;
  }
  std::string all;
  for (const auto& p : names)
  {
    all += (all.empty() ? "" : ", ") + p;
  }
  throw UsageError("--tf expects a transfer-function preset (" + all + ") or a file, got '" + tf +
    "': no preset has that name and no file of that name exists");
#else
  (void)tf;
#endif
}
} // namespace cli
