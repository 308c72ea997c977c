#!/usr/bin/python3
"""Speed against accuracy: render time (log) against PSNR for every image of a results CSV, one
colour per data set and one marker per setting, so several data sets in one job stay apart.
Usage: speed_accuracy_chart.py RESULTS.csv OUT.png [TITLE]"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = "osD^v<>pPX*h"


def main():
    rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "ok" and r["psnr_db"]]
    datasets = sorted({os.path.basename(r["dataset"].rstrip("/")) for r in rows})
    settings = sorted({r["setting"] or "(default)" for r in rows})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    series = {}
    for r in rows:
        key = (os.path.basename(r["dataset"].rstrip("/")), r["setting"] or "(default)")
        series.setdefault(key, []).append((float(r["render_seconds"]), float(r["psnr_db"])))
    for (dataset, setting), pts in sorted(series.items()):
        ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=26,
                   color=colours[datasets.index(dataset) % len(colours)],
                   marker=MARKERS[settings.index(setting) % len(MARKERS)],
                   label=setting if len(datasets) == 1 else dataset + ": " + setting)
    ax.set_xscale("log")
    ax.set_xlabel("render time (s, log scale)")
    ax.set_ylabel("PSNR against the reference (dB)")
    ax.set_title(sys.argv[3] if len(sys.argv) > 3 else "Render time against error")
    ax.grid(True, which="both", alpha=0.3)
    if series:
        ax.legend(fontsize=7)
    else:
        ax.text(0.5, 0.5, "no image with an error figure", ha="center", transform=ax.transAxes)
    fig.tight_layout()
    out = sys.argv[2]
    tmp = os.path.join(os.path.dirname(os.path.abspath(out)), "." + os.path.basename(out) + ".tmp.png")
    fig.savefig(tmp)
    os.replace(tmp, out)  # atomic: a reader never sees half a chart


main()
