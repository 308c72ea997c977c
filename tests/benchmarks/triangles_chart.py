"""Chart of `adaptivert bench triangles`: closest-hit Mrays/s per scene and engine (1 and 2
threads, log scale), the paper's R/O tables as throughput against memory, and (when measured)
FindClosestPoint queries/s of vtkTriangleGridLocator against VTK's cell locators.
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
if points:
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(21, 6))
else:
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(15, 6))
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
for s in scenes:
    t = [r for r in rows if r["scene"] == s and r["group"] == "table"]
    if not t:
        continue
    line = ax2.plot([r["bytesPerTriangle"] for r in t], [r["closest1"]["median"] for r in t], "o", label=s)
    for r in t:
        ax2.annotate(kind(r["engine"]), (r["bytesPerTriangle"], r["closest1"]["median"]),
                     fontsize=6, xytext=(3, 2), textcoords="offset points", color=line[0].get_color())
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
