"""Chart for paraview_bench.py: per volume, the peak memory of each rank (above its pvbatch
baseline, the largest rank and the mean) and the reduction and frame times against the ranks."""
import json
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

data = json.load(open(sys.argv[1]))
volumes = list(dict.fromkeys(r["volume"] for r in data["rows"]))
fig, axes = plt.subplots(len(volumes), 2, figsize=(11, 4.2 * len(volumes)), squeeze=False)
for row_axes, volume in zip(axes, volumes):
    rows = sorted((r for r in data["rows"] if r["volume"] == volume), key=lambda r: r["ranks"])
    ranks = [r["ranks"] for r in rows]
    above = [[p["peak_reduce_mb"] - p["baseline_mb"] for p in r["per_rank"]] for r in rows]
    ax = row_axes[0]
    width = 0.35
    xs = range(len(rows))
    ax.bar([x - width / 2 for x in xs], [max(a) for a in above], width, label="largest rank")
    ax.bar([x + width / 2 for x in xs], [statistics.mean(a) for a in above], width, label="mean of the ranks")
    for x, a in zip(xs, above):
        ax.annotate("%.0f" % max(a), (x - width / 2, max(a)), ha="center", va="bottom", fontsize=8)
    ax.set_xticks(list(xs), ["%d rank%s" % (n, "" if n == 1 else "s") for n in ranks])
    ax.set_ylabel("peak memory while reducing, MB\n(above each rank's pvbatch baseline)")
    ax.set_title("%s, %d tets: memory per rank" % (volume, rows[0]["tets_budget"]), fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", alpha=0.3)
    ax = row_axes[1]
    for key, label, marker in (("reduce_seconds", "reduce (median)", "o"), ("render_seconds", "one frame (median)", "s")):
        med = [statistics.median(r[key]) for r in rows]
        lo = [med[i] - min(r[key]) for i, r in enumerate(rows)]
        hi = [max(r[key]) - med[i] for i, r in enumerate(rows)]
        ax.errorbar(ranks, med, yerr=[lo, hi], marker=marker, capsize=3, label=label)
    ax.set_xticks(ranks)
    ax.set_xlabel("ranks (on %d cores: more ranks than cores share them)" % data["cpus"])
    ax.set_ylabel("seconds (min-max bars)")
    ax.set_yscale("log")
    ax.set_title("time (the machine is shared: ratios only)", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
fig.suptitle("AdaptiveRT in ParaView 5.11 under mpiexec (%s, %s)" % (data["commit"], data["date"]), fontsize=11)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
