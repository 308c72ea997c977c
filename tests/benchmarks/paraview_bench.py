"""The ParaView benchmark (tests/benchmarks/paraview-results/README.md): time and peak memory per
rank of the distributed reduction and of 'Tet Ray Cast Volume', for 1, 2 and 4 ranks, on the full
CT head (256 x 256 x 108) and on the CT resampled to 512 x 512 x 216. Run by Debian's python3 with
the plugin built (bash cmake/setup.sh paraview) and a display (xvfb-run -a):
    /usr/bin/python3 tests/benchmarks/paraview_bench.py [--reuse] [OUTDIR]
Writes OUTDIR/paraview.json, paraview.md and (paraview_chart.py) paraview.png. With --reuse, a
configuration whose run finished (its times.json in build/paraview/bench) is not run again."""
import datetime
import glob
import json
import os
import platform
import statistics
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(root, "paraview", "Testing"))
prefix = os.path.join(root, "build", "paraview", "prefix", "usr")
os.environ.setdefault("ART_PV_PYTHONPATH", os.path.join(prefix, "lib", "python3", "dist-packages"))
os.environ.setdefault("ART_PV_PLUGIN_DIR", os.path.join(root, "build", "paraview", "lib", "paraview-5.11", "plugins",
                                                        "AdaptiveRT"))
os.environ.setdefault("ART_PVBATCH", os.path.join(prefix, "bin", "pvbatch"))
os.environ.setdefault("ART_MPIEXEC", "/usr/bin/mpiexec")
import pvrun  # noqa: E402

args = sys.argv[1:]
reuse = "--reuse" in args
args = [a for a in args if a != "--reuse"]
out = os.path.abspath(args[0] if args else os.path.join(here, "paraview-results"))
work = os.path.join(root, "build", "paraview", "bench")
os.makedirs(work, exist_ok=True)
full = os.path.join(root, "data", "full", "ct-head.mha")
if not os.path.exists(full):
    sys.exit("needs %s (data/fetch ct-head)" % full)

# The volumes as .vti, which each rank reads in part (the .mha is read whole by one rank).
CONVERT = """import sys
from vtkmodules.vtkIOImage import vtkMetaImageReader
from vtkmodules.vtkImagingCore import vtkImageResample
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
r = vtkMetaImageReader(); r.SetFileName(sys.argv[1])
src = r
if float(sys.argv[3]) != 1:
    src = vtkImageResample(); src.SetInputConnection(r.GetOutputPort()); src.SetInterpolationModeToLinear()
    for a in range(3): src.SetAxisMagnificationFactor(a, float(sys.argv[3]))
w = vtkXMLImageDataWriter(); w.SetInputConnection(src.GetOutputPort()); w.SetFileName(sys.argv[2])
assert w.Write()"""
volumes = [("ct-head 256x256x108", "ct-head.vti", 1, 200000, 5), ("ct-head resampled 512x512x216", "ct-head-512.vti",
                                                                    2, 500000, 3)]
ranks_list = [1, 2, 4]
FRAMES = 5
rows = []
for label, name, factor, tets, repeats in volumes:
    vti = os.path.join(work, name)
    if not os.path.exists(vti):
        subprocess.run(["/usr/bin/python3", "-c", CONVERT, full, vti, str(factor)], check=True,
                       env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    for ranks in ranks_list:
        d = os.path.join(work, "%s-np%d" % (name, ranks))
        if reuse and os.path.exists(os.path.join(d, "times.json")):
            print("%s, %d rank(s): kept from the last run" % (label, ranks), file=sys.stderr, flush=True)
        else:
            for f in glob.glob(os.path.join(d, "*")):
                os.remove(f)
            print("%s, %d rank(s)..." % (label, ranks), file=sys.stderr, flush=True)
            pvrun.pvbatch(os.path.join(here, "paraview_bench_run.py"), vti, str(tets), str(repeats), str(FRAMES), d,
                          ranks=ranks, timeout=7200)

        def recs(tag):
            return sorted((json.load(open(f)) for f in glob.glob(os.path.join(d, tag + "-rank*.json"))),
                          key=lambda r: r["rank"])
        times = json.load(open(os.path.join(d, "times.json")))
        base, reduced, rendered = recs("baseline"), recs("reduce%d" % (repeats - 1)), recs("rendered")
        per_rank = []
        for b, r, g in zip(base, reduced, rendered):
            per_rank.append({"rank": r["rank"], "extent": r.get("piece_extent"), "given": r.get("input_extent"),
                             "tets": r["cells"], "build_seconds": r.get("build_seconds", [0])[0],
                             "pilot_seconds": r.get("piece_pilot_seconds", [0])[0],
                             "baseline_mb": b["peak_kb"] / 1024, "peak_reduce_mb": r["peak_kb"] / 1024,
                             "peak_render_mb": g["peak_kb"] / 1024})
        rows.append({"volume": label, "file": name, "tets_budget": tets, "ranks": ranks, "tets": times["tets"],
                     "weighted_rms": reduced[0].get("weighted_rms_error", [0])[0],
                     "reduce_seconds": times["reduce_seconds"], "render_seconds": times["render_seconds"],
                     "per_rank": per_rank, "image": os.path.relpath(os.path.join(d, "frame.png"), root)})

# Image agreement: each split's frame against one rank's of the same volume (the meshes differ:
# each split is a reduction of its own).
adaptivert = os.path.join(root, "build", "bin", "adaptivert")
for row in rows:
    one = next(r for r in rows if r["volume"] == row["volume"] and r["ranks"] == 1)
    run = subprocess.run([adaptivert, "compare", "--json", "--quiet", os.path.join(root, row["image"]),
                          os.path.join(root, one["image"])],
                         capture_output=True, text=True, check=True)
    row["psnr_vs_one_rank"] = json.loads(run.stdout)["psnr_db"]

commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
result = {"date": datetime.date.today().isoformat(), "commit": commit, "machine": platform.node(),
          "cpus": os.cpu_count(), "frames": FRAMES, "size": [500, 500], "transfer_function": "ct-skin-bone",
          "rows": rows}
os.makedirs(out, exist_ok=True)
json.dump(result, open(os.path.join(out, "paraview.json"), "w"), indent=1)


def spread(v):
    return "%.2f (%.2f-%.2f)" % (statistics.median(v), min(v), max(v))


lines = ["| volume | ranks | tets | weighted RMS | reduce s, median (min-max) | render s, median (min-max) | "
         "peak MB per rank after reducing (above baseline) | after rendering | PSNR vs 1 rank |",
         "|---|---|---|---|---|---|---|---|---|"]
for r in rows:
    lines.append("| %s | %d | %d | %.2f | %s | %s | %s | %s | %s |" % (
        r["volume"], r["ranks"], r["tets"], r["weighted_rms"], spread(r["reduce_seconds"]), spread(r["render_seconds"]),
        ", ".join("%.0f (%.0f)" % (p["peak_reduce_mb"], p["peak_reduce_mb"] - p["baseline_mb"]) for p in r["per_rank"]),
        ", ".join("%.0f" % p["peak_render_mb"] for p in r["per_rank"]),
        "-" if r["ranks"] == 1 else "%.2f dB" % r["psnr_vs_one_rank"]))
open(os.path.join(out, "paraview.md"), "w").write(
    "ParaView benchmark, %s at %s on %s (%d cores)\n\n" % (result["date"], commit, result["machine"], result["cpus"])
    + "\n".join(lines) + "\n")
print("\n".join(lines))
subprocess.run(["/usr/bin/python3", os.path.join(here, "paraview_chart.py"), os.path.join(out, "paraview.json"),
                os.path.join(out, "paraview.png")], check=True)
