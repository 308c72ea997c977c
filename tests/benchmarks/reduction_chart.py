"""Chart for `adaptivert bench reduction`: RMS error against vertices and against tets for each
refinement series, uniform downsampling and VTK's quadric decimation; build time against vertices."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

src, png = sys.argv[1], sys.argv[2]
d = json.load(open(src))
markers = {"bisection": "o", "relocated": "D", "edge": "v", "anisotropic": "*"}
fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
for i, s in enumerate(d["series"]):
    rows, timed = s["rows"], s.get("timed", [])
    m, c = markers.get(s["name"], "o"), "C%d" % i
    for ax, x in ((axes[0], "vertices"), (axes[1], "tets")):
        ax.plot([r[x] for r in rows], [r["rms"] for r in rows], m + "-", color=c, label=s["name"])
        if timed:
            ax.plot([r[x] for r in timed], [r["rms"] for r in timed], m, color=c, mfc="none", ms=11,
                    label=s["name"] + ", run alone")
    axes[2].plot([r["vertices"] for r in rows + timed], [r["seconds"] for r in rows + timed], m, color=c,
                 label=s["name"])
# Uniform downsampling at the vertex counts of every mesh (it depends on the count alone).
uni = sorted({(r["uniform_vertices"], r["uniform_rms"]) for s in d["series"] for r in s["rows"] + s.get("timed", [])})
axes[0].plot([u[0] for u in uni], [u[1] for u in uni], "^:", color="grey", label="uniform downsampling")
if d.get("quadric"):
    q = d["quadric_rows"]
    for ax, x in ((axes[0], "vertices"), (axes[1], "tets")):
        ax.plot([r[x] for r in q], [r["covered_rms"] for r in q], "s--", color="black", alpha=0.6,
                label="quadric decimation (covered voxels)")
for ax, x in ((axes[0], "vertices"), (axes[1], "tetrahedra")):
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(x)
    ax.set_ylabel("RMS error (data units)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
axes[2].set_xscale("log")
axes[2].set_yscale("log")
axes[2].set_xlabel("vertices")
axes[2].set_ylabel("build seconds (cumulative over a run of levels)")
axes[2].grid(True, which="both", alpha=0.3)
axes[2].legend(fontsize=7)
dims = " x ".join(str(int(v)) for v in d["dims"])
fig.suptitle("Reduction of %s (%s voxels), %d threads, commit %s" % (d["input"].split("/")[-1], dims, d["threads"],
                                                                      d["commit"]))
fig.tight_layout()
fig.savefig(png, dpi=110)
