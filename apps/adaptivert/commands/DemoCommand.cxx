// adaptivert demo: the main job on the embedded default data. Loads the default CT head,
// reduces it to an adaptive tet mesh, renders it cell by cell, and reports the output path, the
// tet count, the render time and the error against the full-resolution voxel render. It is
// `adaptivert render` with the defaults below, so the demo and the tool never drift apart.
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"
#include "cli/ResourcePath.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("input", 'i', "FILE", "volume to use", cli::DataDir() + "/ct-head-128.mha");
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
  // The demo reduces a volume; given a mesh or a surface, render refused the --tets it was passed
  // ('--tets does not apply to a surface'), an option the user never gave.
  art::DataKind kind = art::DataKind::Volume;
  try
  {
    kind = art::KindOf(o.Get("input"));
  }
  catch (const art::Error&)
  {
    // a missing or unknown file: render names it
  }
  if (kind != art::DataKind::Volume)
  {
    throw cli::UsageError("--input must be a volume (the demo reduces it); '" + o.Get("input") + "' is a " +
      art::KindName(kind) + ": render it with 'adaptivert render " + o.Get("input") + " -o OUT.png'");
  }
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
