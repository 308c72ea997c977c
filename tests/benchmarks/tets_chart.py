"""Chart for `adaptivert bench tets`: render time against PSNR for every method."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

data = json.load(open(sys.argv[1]))
methods = {}
for r in data["rows"]:
    methods.setdefault(r["method"], []).append(r)
fig, ax = plt.subplots(figsize=(8, 5.5))
markers = "osD^vP*X"
for i, (name, rows) in enumerate(methods.items()):
    rows = sorted(rows, key=lambda r: (r["vertices"], r["tets"]))  # along the reduction series
    xs = [r["seconds"] for r in rows]
    ys = [min(r["psnr"], 80) for r in rows]
    ax.plot(xs, ys, marker=markers[i % len(markers)], label=name)
    for r in rows:
        label = "voxels" if r["mesh"] == "voxels" else ("full" if r["mesh"] == "full resolution" else f'{r["tets"] // 1000}k')
        ax.annotate(label, (r["seconds"], min(r["psnr"], 80)), fontsize=7, xytext=(3, 3), textcoords="offset points")
ax.set_xscale("log")
ax.set_xlabel("render time, s (median, log scale)")
ax.set_ylabel("PSNR against the voxel reference, dB")
ax.set_title(f'CT head {data["width"]}x{data["height"]}, {data["transfer_function"]}: time vs error ({data["commit"]}, {data["threads"]} threads)')
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
