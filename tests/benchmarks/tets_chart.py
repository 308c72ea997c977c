"""Chart for `adaptivert bench tets`: render time against PSNR for every method, one line per
method and reduction series (solid: the lattice series, dashed: anisotropic), full resolution at
the end of each line, VTK's FixedPoint on the voxels as a star."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

data = json.load(open(sys.argv[1]))
rows = data["rows"]
styles = {"relocated": "-", "bisection": "-", "anisotropic": "--"}
reduced = [r.get("series", "relocated") for r in rows if r.get("series", "relocated") not in ("full", "voxels")]
series = list(dict.fromkeys(reduced)) or ["full"]
methods = list(dict.fromkeys(r["method"] for r in rows if r.get("series") != "voxels"))
fig, ax = plt.subplots(figsize=(9, 6))
markers = "osD^vP*X"


def label_of(r):
    if r["mesh"] == "full resolution":
        return "full"
    return f'{round(r["tets"] / 1000)}k' + ("a" if r.get("series") == "anisotropic" else "")


for i, name in enumerate(methods):
    for s in series:
        pts = [r for r in rows if r["method"] == name and (r.get("series", "relocated") in (s, "full"))]
        pts = sorted(pts, key=lambda r: (r["vertices"], r["tets"]))  # along the reduction series
        if not pts:
            continue
        ax.plot([r["seconds"] for r in pts], [min(r["psnr"], 80) for r in pts], styles.get(s, "-"),
                marker=markers[i % len(markers)], color="C%d" % i, label=f"{name} ({s})", alpha=0.9)
        for r in pts:
            if s == series[0] or r["mesh"] != "full resolution":
                ax.annotate(label_of(r), (r["seconds"], min(r["psnr"], 80)), fontsize=6, xytext=(3, 3),
                            textcoords="offset points")
for r in rows:
    if r.get("series") == "voxels" or r["mesh"] == "voxels":
        ax.plot([r["seconds"]], [r["psnr"]], "*", color="black", ms=16, label=r["method"])
        ax.axhline(r["psnr"], color="black", lw=0.6, ls=":")
ax.set_xscale("log")
ax.set_xlabel("render time, s (median, log scale; shared, loaded machine)")
ax.set_ylabel("PSNR against the voxel reference, dB")
name = data["input"].split("/")[-1]
ax.set_title(f'{name} {data["width"]}x{data["height"]}, {data["transfer_function"]}: time vs error '
             f'({data["commit"]}, {data["threads"]} threads)', fontsize=10)
ax.grid(True, which="both", alpha=0.3)
# Below the curves (time rises with PSNR, so the lower right is empty), the star shrunk to fit.
ax.legend(fontsize=6, ncol=2, loc="lower right", markerscale=0.5)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
