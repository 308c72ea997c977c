// adaptivert demo: the main job on the embedded default data. Loads the default CT head,
// reduces it to an adaptive tet mesh, renders it, and reports the output path, the tet count,
// the render time and the error against the full-resolution render.
#include "Command.h"
#include "DataLoader.h"
#include "Json.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <cstdio>
#include <filesystem>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("input", 'i', "FILE", "volume to use", std::string(ART_DATA_DIR) + "/ct-head-128.mha");
  o.Add("output", 'o', "FILE", "image to write", "adaptivert-demo.png");
}

int Run(const cli::Options& o)
{
  const std::string in = o.Get("input");
  auto vol = art::LoadVolume(in);
  int d[3];
  vol->GetDimensions(d);
  double r[2];
  vol->GetPointData()->GetScalars()->GetRange(r);
  cli::Json j;
  j.Set("input", in).Set("voxels", static_cast<long long>(d[0]) * d[1] * d[2]);
  if (!o.Flag("json"))
  {
    std::printf("input        %s (%d x %d x %d voxels, range %g .. %g)\n", in.c_str(), d[0], d[1],
      d[2], r[0], r[1]);
    // The reducer (issue 4) and the tet caster (issue 5) are not built yet; say so plainly.
    std::printf("reduce       not available yet: the least-squares tet reducer is still to be built\n");
    std::printf("render       not available yet: the cell-by-cell tet ray caster is still to be built\n");
    std::printf("output       none written\n");
  }
  else
  {
    j.Set("reduce", "not available").Set("render", "not available");
    std::printf("%s\n", j.Str().c_str());
  }
  return cli::ExitOk;
}

cli::Registrar reg({ "demo",
  "the main job on the embedded CT head: reduce, render, and report time and error",
  "adaptivert demo [options]", "  adaptivert demo\n  adaptivert demo -o head.png --json\n",
  Declare, Run });
} // namespace
