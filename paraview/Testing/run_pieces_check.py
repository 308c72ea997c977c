"""The distributed reduction under mpirun (Debian's /usr/bin/python3 drives; pvbatch runs):
    run_pieces_check.py RANKS mha|vti TETS
N ranks reduce the default CT (each rank its part: from a .vti each rank's reader reads only its
extent; the compressed .mha, which cannot be read in parts, is read by rank 0, which hands the
others their parts) and draw it with 'Tet Ray Cast Volume';
one rank then draws the mesh the N ranks wrote, and one rank reduces the whole CT. Checks: the N
ranks draw what one rank draws (PSNR >= MIN_PSNR dB); no rank reduced the whole extent, and from a
.vti none was given it; the pieces' tets add up to the budget; the whole volume's weighted RMS is
within RMS_SLACK of the one-rank reduction's; an error bound (a fraction of the whole volume's
range) is met by the pieces together. Prints the peak memory of each rank beside the one
rank's (above each process's baseline before reading)."""
import glob
import json
import os
import shutil
import subprocess
import sys

import pvrun

MIN_PSNR = 40.0
RMS_SLACK = 0.05
here = os.path.dirname(os.path.abspath(__file__))
ranks, kind, tets = int(sys.argv[1]), sys.argv[2], int(sys.argv[3])
source = os.environ["ART_SOURCE_DIR"]
out = os.path.join(os.environ["ART_TEST_OUTPUT"], "pv-pieces-%s-np%d" % (kind, ranks))
adaptivert = os.path.join(os.environ["ART_BIN"], "adaptivert")
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)

volume = os.path.join(source, "data", "ct-head-128.mha")
if kind == "vti":
    vti = os.path.join(out, "ct-head-128.vti")
    subprocess.run(["/usr/bin/python3", "-c", "import sys\n"
                    "from vtkmodules.vtkIOImage import vtkMetaImageReader\n"
                    "from vtkmodules.vtkIOXML import vtkXMLImageDataWriter\n"
                    "r = vtkMetaImageReader(); r.SetFileName(sys.argv[1])\n"
                    "w = vtkXMLImageDataWriter(); w.SetInputConnection(r.GetOutputPort()); w.SetFileName(sys.argv[2])\n"
                    "assert w.Write()", volume, vti], check=True)
    volume = vti


def pvbatch(n, *args):
    pvrun.pvbatch(os.path.join(here, "pv_pieces.py"), *args, ranks=n)


def records(tag):
    return sorted((json.load(open(f)) for f in glob.glob(os.path.join(out, tag + "-rank*.json"))),
                  key=lambda r: r["rank"])


pvbatch(ranks, "reduce", volume, out, str(tets))
pvbatch(1, "draw", os.path.join(out, "mesh-%d.pvtu" % ranks), out)
pvbatch(1, "reduce", volume, out, str(tets))

fails = []
run = subprocess.run([adaptivert, "compare", "--json", "--quiet", os.path.join(out, "reduce-%d.png" % ranks),
                      os.path.join(out, "draw-1.png"), "--min-psnr", str(MIN_PSNR),
                      "--diff", os.path.join(out, "diff.png")], capture_output=True, text=True)
f = json.loads(run.stdout)
print("%d ranks draw what one rank draws of their mesh: PSNR %.2f dB (bound %.0f), max |diff| %.4f, SSIM %.5f"
      % (ranks, f["psnr_db"], MIN_PSNR, f["max_abs"], f["ssim"]))
if run.returncode != 0:
    fails.append("image")

pieces, whole = records("reduced-%d" % ranks), records("reduced-1")
base_n, base_1 = records("baseline-%d" % ranks), records("baseline-1")
assert len(pieces) == ranks and len(whole) == 1 and len(base_n) == ranks, (len(pieces), len(whole))
total = sum(p["cells"] for p in pieces)
print("one rank: %d tets, weighted RMS %.2f, peak %.0f MB (%.0f MB above its baseline)"
      % (whole[0]["cells"], whole[0].get("weighted_rms_error", [0])[0] if "weighted_rms_error" in whole[0] else 0,
         whole[0]["peak_kb"] / 1024, (whole[0]["peak_kb"] - base_1[0]["peak_kb"]) / 1024))
for p, b in zip(pieces, base_n):
    print("rank %d: extent %s (given %s), %d tets of a share of %d, peak %.0f MB (%.0f MB above its baseline)"
          % (p["rank"], [int(v) for v in p["piece_extent"]], [int(v) for v in p["input_extent"]], p["cells"],
             p["piece_target_tets"][0], p["peak_kb"] / 1024, (p["peak_kb"] - b["peak_kb"]) / 1024))
    if p["piece_extent"] == [0, 127, 0, 127, 0, 53]:
        fails.append("rank %d reduced the whole extent" % p["rank"])
    if kind == "vti" and p["input_extent"] != p["piece_extent"]:
        fails.append("rank %d was given %s" % (p["rank"], p["input_extent"]))
rms_n, rms_1 = pieces[0]["weighted_rms_error"][0], whole[0]["weighted_rms_error"][0]
print("the pieces: %d tets in all (budget %d), weighted RMS %.2f of the whole volume (one rank %.2f, %+.1f%%)"
      % (total, tets, rms_n, rms_1, 100 * (rms_n / rms_1 - 1)))
if abs(total - tets) > 0.01 * tets or pieces[0]["total_tets"][0] != total:
    fails.append("tets %d for a budget of %d" % (total, tets))
if rms_n > (1 + RMS_SLACK) * rms_1:
    fails.append("weighted RMS %.2f against %.2f" % (rms_n, rms_1))
bounded, bounded_1 = records("bounded-%d" % ranks), records("bounded-1")
b = bounded[0]
limit = 0.04 * (b["scalar_range_max"][0] - b["scalar_range_min"][0])
print("error bound 4%% of the range (%.1f): the pieces reach RMS %.2f with %d tets (one rank %.2f with %d; piece bounds %s)"
      % (limit, b["rms_error"][0], b["total_tets"][0], bounded_1[0]["rms_error"][0], bounded_1[0]["cells"],
         " ".join("%.1f" % p["piece_target_error"][0] for p in bounded)))
if not b["rms_error"][0] <= limit or b["target_error"][0] != limit and abs(b["target_error"][0] - limit) > 1e-6 * limit:
    fails.append("error bound: RMS %.2f for %.2f (target_error %.2f)" % (b["rms_error"][0], limit, b["target_error"][0]))
peak_n = max(p["peak_kb"] - b["peak_kb"] for p, b in zip(pieces, base_n))
peak_1 = whole[0]["peak_kb"] - base_1[0]["peak_kb"]
print("peak memory above baseline: largest of %d ranks %.0f MB, one rank %.0f MB (%.2f x)"
      % (ranks, peak_n / 1024, peak_1 / 1024, peak_n / peak_1))
if fails:
    sys.exit("failed: " + "; ".join(fails))
print("ok")
