"""Chart of `adaptivert bench triangles`: the default grid's ratios to Embree (1 thread) against
the targets, closest-hit Mrays/s per scene and engine (1 and 2 threads, log scale), the paper's
R/O tables as throughput against memory (when run), and (when measured) FindClosestPoint
queries/s of vtkTriangleGridLocator against VTK's cell locators.
Usage: /usr/bin/python3 triangles_chart.py triangles.json triangles.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

data = json.load(open(sys.argv[1]))
rows = data["rows"]
scenes = [r["scene"] for r in data["ratios"]]
main = [r for r in rows if r["group"] in ("ours", "anchor")]


def kind(name):
    """One label per engine across scenes: drops grid sizes and depths from our names."""
    if name.startswith("uniform grid"):
        return "uniform grid"
    if name.startswith(("R[", "O[")):
        label = name[: name.index("]") + 1]
        return label + (" no-top" if "no-top" in name else "")
    return name.replace("Embree 3 rtcIntersect1/rtcOccluded1", "Embree 3").replace("VTK vtk", "VTK ")


for r in main:
    r["kind"] = kind(r["engine"])
engines = []
for r in main:
    if r["kind"] not in engines:
        engines.append(r["kind"])


points = data.get("closestPoint", [])
tables = [r for r in rows if r["group"] == "table"]
panels = 2 + bool(tables) + bool(points)
fig, axes = plt.subplots(1, panels, figsize=(7 * panels, 6))
ax0, ax1 = axes[0], axes[1]
ax2 = axes[2] if tables else None
ax3 = axes[-1] if points else None

# The default grid over Embree, one thread: target 1.0, floors 0.8 (closest) and 0.7.
queries = [("closestVsEmbree1", "closest", 0.8), ("shadowVsEmbree1", "shadow", 0.7), ("allHitsVsEmbree1", "all hits", 0.7)]
rw = 0.8 / len(queries)
for k, (key, label, floor) in enumerate(queries):
    vals = [r.get(key, 0) for r in data["ratios"]]
    xs = [i + (k - len(queries) / 2) * rw + rw / 2 for i in range(len(scenes))]
    bars = ax0.bar(xs, vals, rw * 0.9, label="%s (floor %.1f)" % (label, floor))
    ax0.hlines([floor] * len(xs), [x - rw / 2 for x in xs], [x + rw / 2 for x in xs], colors=bars[0].get_facecolor(),
               linestyles="dotted")
    for x, v in zip(xs, vals):
        ax0.annotate("%.2f" % v, (x, v), fontsize=6, ha="center", xytext=(0, 2), textcoords="offset points")
ax0.axhline(1.0, color="black", linewidth=1, label="target: Embree's rate")
ax0.set_xticks(range(len(scenes)))
ax0.set_xticklabels(["%s\n%.0f B/tri" % (r["scene"], r.get("bytesPerTriangle", 0)) for r in data["ratios"]],
                    fontsize=8)
ax0.set_ylabel("default grid R[12,4] / Embree 3, 1 thread (median of runs)")
ax0.set_title("Ratios to Embree (dotted: the floors; B/tri target <= 64)")
ax0.legend(fontsize=7)
ax0.grid(axis="y", alpha=0.3)
width = 0.8 / max(1, len(engines))
for k, eng in enumerate(engines):
    v1, v2 = [], []
    for s in scenes:
        r = next((r for r in main if r["scene"] == s and r["kind"] == eng), None)
        v1.append(r["closest1"]["median"] if r else 0)
        v2.append(r["closest2"]["median"] if r and "closest2" in r else 0)
    xs = [i + (k - len(engines) / 2) * width + width / 2 for i in range(len(scenes))]
    ax1.bar(xs, v1, width * 0.9, label=eng)
    ax1.scatter([x for x, v in zip(xs, v2) if v > 0], [v for v in v2 if v > 0], marker="_", s=80, color="black",
                zorder=3)
ax1.set_xticks(range(len(scenes)))
ax1.set_xticklabels(scenes)
ax1.set_yscale("log")
ax1.set_ylabel("closest hit, Mrays/s (bar: 1 thread, dash: 2 threads)")
ax1.set_title("Primary rays: TriangleGrid vs Embree 3 and VTK locators")
ax1.legend(fontsize=7)
ax1.grid(axis="y", which="both", alpha=0.3)

markers = {"R": "o", "O": "s"}
for s in scenes if ax2 else []:
    t = [r for r in rows if r["scene"] == s and r["group"] == "table"]
    if not t:
        continue
    line = ax2.plot([r["bytesPerTriangle"] for r in t], [r["closest1"]["median"] for r in t], "o", label=s)
    for r in t:
        ax2.annotate(kind(r["engine"]), (r["bytesPerTriangle"], r["closest1"]["median"]),
                     fontsize=6, xytext=(3, 2), textcoords="offset points", color=line[0].get_color())
if ax2:
    ax2.set_xscale("log")
    ax2.set_xlabel("bytes per triangle (structure + triangle store)")
    ax2.set_ylabel("closest hit, Mrays/s, 1 thread")
    ax2.set_title("The paper's tables: R[thr,N] and O[thr,w]")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=7)
if points:
    pscenes = []
    for r in points:
        if r["scene"] not in pscenes:
            pscenes.append(r["scene"])
    pengines = []
    for r in points:
        if r["engine"] not in pengines:
            pengines.append(r["engine"])
    w = 0.8 / max(1, len(pengines))
    for k, eng in enumerate(pengines):
        vals, lo, hi = [], [], []
        for sc in pscenes:
            r = next((r for r in points if r["scene"] == sc and r["engine"] == eng), None)
            q = r["queriesPerSecond"] if r else {"median": 0, "min": 0, "max": 0}
            vals.append(q["median"])
            lo.append(q["median"] - q["min"])
            hi.append(q["max"] - q["median"])
        xs = [i + (k - len(pengines) / 2) * w + w / 2 for i in range(len(pscenes))]
        ax3.bar(xs, vals, w * 0.9, yerr=[lo, hi], capsize=2,
                label=eng.replace("vtkTriangleGridLocator ", "ours: ").replace("VTK vtk", "VTK "))
    ax3.set_xticks(range(len(pscenes)))
    ax3.set_xticklabels(pscenes)
    ax3.set_yscale("log")
    ax3.set_ylabel("FindClosestPoint queries/s, 1 thread (median, min-max)")
    ax3.set_title("Closest point: same %d points per scene (in box, near, far)" % data.get("closestPointQueries", 0))
    ax3.legend(fontsize=7)
    ax3.grid(axis="y", which="both", alpha=0.3)
fig.suptitle("adaptivert bench triangles, %s, commit %s, %s" % (data["date"], data["commit"], data["cpu"]), fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=90)
