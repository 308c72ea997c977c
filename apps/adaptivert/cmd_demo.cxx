// adaptivert demo: the main job on the embedded default data. Loads the default CT head,
// reduces it to an adaptive tet mesh, renders it cell by cell, and reports the output path, the
// tet count, the render time and the error against the full-resolution voxel render. It is
// `adaptivert render` with the defaults below, so the demo and the tool never drift apart.
#include "Command.h"
#include "Error.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("input", 'i', "FILE", "volume to use", std::string(ART_DATA_DIR) + "/ct-head-128.mha");
  o.Add("output", 'o', "FILE", "image to write", "adaptivert-demo.png");
  o.Add("tets", 0, "N", "tet budget of the reduction", "100000");
  o.Add("size", 's', "WxH", "image size", "500x500");
}

int Run(const cli::Options& o)
{
  const cli::Command* render = cli::FindCommand("render");
  if (!render)
  {
    throw art::Error("this build has no render command");
  }
  std::vector<std::string> args = { o.Get("input"), "-o", o.Get("output"), "--size", o.Get("size"),
    "--threads", o.Get("threads") };
#ifdef ART_HAVE_Reduction
  args.insert(args.end(), { "--tets", o.Get("tets") });
#else
  std::fprintf(stderr, "demo: the reducer is not in this build; rendering full-resolution tets\n");
#endif
  for (const char* flag : { "json", "quiet", "verbose" })
  {
    if (o.Flag(flag))
    {
      args.push_back(std::string("--") + flag);
    }
  }
  return cli::RunCommand(*render, args);
}

cli::Registrar reg({ "demo",
  "the main job on the embedded CT head: reduce, render, and report time and error",
  "adaptivert demo [options]",
  "  adaptivert demo\n  adaptivert demo --tets 50000 -o head.png --json\n", Declare, Run });
} // namespace
