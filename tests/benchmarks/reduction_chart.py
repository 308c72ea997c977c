"""Chart for `adaptivert bench reduction`: error against tets for the reducer and its anchors."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

src, png = sys.argv[1], sys.argv[2]
d = json.load(open(src))
rows = d["rows"]
fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
for ax, key, label in ((axes[0], "rms", "RMS error"), (axes[1], "max", "max error")):
    ax.plot([r["tets"] for r in rows], [r[key] for r in rows], "o-", label="least-squares reducer (ours)")
    if d.get("quadric"):
        ax.plot([r["quadric_tets"] for r in rows], [r["quadric_" + key] for r in rows], "s--",
                label="vtkUnstructuredGridQuadricDecimation")
        if key == "rms":
            ax.plot([r["quadric_tets"] for r in rows], [r["quadric_covered_rms"] for r in rows], "s:",
                    color="C1", alpha=0.6, label="quadric, covered voxels only")
            if "ours_at_quadric_tets_covered_rms" in rows[0]:
                ax.plot([r["ours_at_quadric_tets"] for r in rows], [r["ours_at_quadric_tets_covered_rms"] for r in rows],
                        "o:", color="C0", alpha=0.6, label="ours at its tets, on the voxels it covers")
    ax.plot([r["uniform_tets"] for r in rows], [r["uniform_" + key] for r in rows], "^:",
            label="uniform downsampling (same vertices)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("tetrahedra")
    ax.set_ylabel(label + " (HU)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
dims = " x ".join(str(int(v)) for v in d["dims"])
fig.suptitle("Reduction of %s (%s voxels), commit %s" % (d["input"].split("/")[-1], dims, d["commit"]))
fig.tight_layout()
fig.savefig(png, dpi=110)
