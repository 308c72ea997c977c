"""Scaling table and chart of `adaptivert bench tets` over several volumes (tets_scaling.sh;
usage: tets_scaling_chart.py OUT [FOLDER...]):
per volume, render time against PSNR of our exact caster on each mesh series, FixedPoint as a
point, and the smallest mesh reaching FixedPoint's PSNR with its speed-up."""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

out = sys.argv[1]  # then, optionally, the result folders to take, in order
runs = []
for name in sys.argv[2:] or ["ct128", "ct256", "ct512", "brain"]:
    path = os.path.join(out, name, "tets.json")
    if os.path.exists(path):
        runs.append((name, json.load(open(path))))
if not runs:
    sys.exit("tets_scaling_chart.py: no tets.json under " + out)

lines = ["# Tet ray casting against FixedPoint across volume sizes", "",
         "Per volume: FixedPoint (voxels) and the smallest mesh of each series drawn by `ours exact, ERT 0.99` "
         "that reaches FixedPoint's PSNR against the voxel reference; ratio = FixedPoint's time / ours. "
         "Bunyk = VTK's UG ray cast on the same mesh.", "",
         "| volume | voxels | series | FixedPoint s | FixedPoint dB | smallest mesh at that PSNR | ours s | ours dB | ratio | Bunyk s (same mesh) | ours / Bunyk rate | ns/tet/thread |",
         "|---|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---:|"]
for name, d in runs:
    rows = d["rows"]
    for m in d.get("at_fixedpoint_psnr", []):
        ours = next(r for r in rows if r["mesh"] == m["mesh"] and r["method"] == "ours exact, ERT 0.99")
        bunyk = [r for r in rows if r["mesh"] == m["mesh"] and r["method"].startswith("VTK Bunyk")]
        mesh = m["mesh"] if m["reached"] else "none; best " + m["mesh"]
        bs = "%.3f" % bunyk[0]["seconds"] if bunyk else "-"
        br = "%.1fx" % (bunyk[0]["seconds"] / ours["seconds"]) if bunyk else "-"
        lines.append("| %s | %d | %s | %.3f | %.2f | %s | %.3f | %.2f | %.2fx | %s | %s | %.0f |" % (
            d.get("input_label", name), d["voxels"], m["series"], m["fixedpoint_seconds"], m["fixedpoint_psnr"],
            mesh, m["seconds"], m["psnr"], m["fixedpoint_speedup"], bs, br, ours["ns_per_tet_crossed_per_thread"]))
lines += ["", "Commits: " + ", ".join(sorted({d["commit"] for _, d in runs})) + "; " +
          ", ".join(sorted({d["date"] for _, d in runs}))]
open(os.path.join(out, "scaling.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

fig, axes = plt.subplots(1, len(runs), figsize=(4.2 * len(runs), 4.4), squeeze=False)
for ax, (name, d) in zip(axes[0], runs):
    rows = d["rows"]
    series = sorted({r["series"] for r in rows if r["method"] == "ours exact, ERT 0.99"})
    for s in series:
        pts = sorted((r for r in rows if r["series"] == s and r["method"] == "ours exact, ERT 0.99"), key=lambda r: r["tets"])
        colour = {"reduced": "tab:orange", "full resolution": "tab:blue"}.get(s, "tab:green")
        ax.plot([r["seconds"] for r in pts], [r["psnr"] for r in pts], marker="o", color=colour, label="ours, " + s)
        for r in pts:
            lab = "full" if s == "full resolution" else "%dk" % (r["tets"] // 1000)
            ax.annotate(lab, (r["seconds"], r["psnr"]), fontsize=7, xytext=(3, 3), textcoords="offset points")
    bunyk = sorted((r for r in rows if r["method"].startswith("VTK Bunyk")), key=lambda r: r["tets"])
    if bunyk:
        ax.plot([r["seconds"] for r in bunyk], [r["psnr"] for r in bunyk], marker="s", color="grey", label="VTK Bunyk")
    for r in rows:
        if r["method"].startswith("VTK FixedPoint"):
            ax.plot([r["seconds"]], [r["psnr"]], marker="*", markersize=15, color="black", linestyle="none", label="VTK FixedPoint")
            ax.axhline(r["psnr"], color="black", linewidth=0.6, linestyle=":")
    ax.set_xscale("log")
    ax.set_title("%s\n%d voxels, %s" % (d.get("input_label", name), d["voxels"], d["transfer_function"]), fontsize=9)
    ax.set_xlabel("time per frame, s (log; loaded machine)")
    ax.grid(True, which="both", alpha=0.3)
axes[0][0].set_ylabel("PSNR against the voxel reference, dB")
for ax in axes[0]:
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(os.path.join(out, "scaling.png"), dpi=100)
