#!/usr/bin/python3
"""Collects regions.sh's figures into regions.json (with machine, date, commit), regions.md and
regions.png (tets and rendered PSNR of the region mesh beside the whole-box mesh)."""
import datetime, json, os, platform, subprocess, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
load = lambda n: json.load(open(os.path.join(out, n)))
rows = []
for name in ("ct-bone", "ct-skin", "mni-brain"):
    if not os.path.exists(os.path.join(out, name + "-region.json")):
        continue
    r, b = load(name + "-region.json"), load(name + "-box.json")
    rt, bt = load(name + "-time.json"), load(name + "-box-time.json")
    rr, br = load(name + "-region-render.json"), load(name + "-box-render.json")
    rows.append(dict(name=name, region=r["region"], region_voxels=r["region_voxels"], voxels=r["voxels"],
                     islands_dropped=r["islands_dropped"], covered_voxels=r["covered_voxels"],
                     tets=r["tets"], vertices=r["vertices"], rms_inside=r["rms_error"],
                     region_seconds=r["build_seconds"], whole_box_search_seconds=r["whole_box_seconds"],
                     run_wall_s=rt["wall_s"], run_user_s=rt["user_s"], run_peak_mb=rt["peak_rss_kb"] / 1024,
                     box_tets=b["tets"], box_vertices=b["vertices"], box_target=r["whole_box_tets"],
                     box_reached=r["whole_box_reached"], box_rms_whole=b["rms_error"],
                     box_wall_s=bt["wall_s"], box_peak_mb=bt["peak_rss_kb"] / 1024,
                     region_psnr=rr["psnr_db"], region_ssim=rr["ssim"], region_render_s=rr["render_seconds"],
                     box_psnr=br["psnr_db"], box_ssim=br["ssim"], box_render_s=br["render_seconds"],
                     reference_s=rr["reference_seconds"]))
commit = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
meta = dict(machine=platform.node(), cpu=platform.processor() or platform.machine(), cores=os.cpu_count(),
            date=datetime.datetime.utcnow().isoformat(timespec="seconds") + "Z", commit=commit,
            note="one run each on a machine shared with other builds: times are noisy, ratios are what to read")
json.dump(dict(meta=meta, rows=rows), open(os.path.join(out, "regions.json"), "w"), indent=1)
with open(os.path.join(out, "regions.md"), "w") as f:
    f.write("| data | region | region voxels | region tets | vertices | RMS inside | whole-box tets, equal RMS inside | ratio "
            "| region PSNR / SSIM | whole-box PSNR / SSIM | region run (wall, peak) | render region / box |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for x in rows:
        f.write("| %s | %g:%g | %s (%.1f%%) | %s | %s | %.4g | %s%s | %.1fx | %.2f dB / %.3f | %.2f dB / %.3f | %.0f s, %.0f MB | %.2f / %.2f s |\n" % (
            x["name"], x["region"][0], x["region"][1], f"{x['region_voxels']:,}", 100 * x["region_voxels"] / x["voxels"],
            f"{x['tets']:,}", f"{x['vertices']:,}", x["rms_inside"], f"{x['box_tets']:,}",
            "" if x["box_reached"] else " (not reached)", x["box_tets"] / x["tets"], x["region_psnr"], x["region_ssim"],
            x["box_psnr"], x["box_ssim"], x["run_wall_s"], x["run_peak_mb"], x["region_render_s"], x["box_render_s"]))
fig, ax = plt.subplots(1, 2, figsize=(9, 3.5))
names = [x["name"] for x in rows]
pos = range(len(rows))
ax[0].bar([p - 0.2 for p in pos], [x["tets"] for x in rows], 0.4, label="region mesh")
ax[0].bar([p + 0.2 for p in pos], [x["box_tets"] for x in rows], 0.4, label="whole box, equal RMS inside")
ax[0].set_yscale("log"); ax[0].set_xticks(list(pos)); ax[0].set_xticklabels(names); ax[0].set_ylabel("tets")
ax[0].legend(fontsize=8)
ax[1].bar([p - 0.2 for p in pos], [x["region_psnr"] for x in rows], 0.4, label="region mesh")
ax[1].bar([p + 0.2 for p in pos], [x["box_psnr"] for x in rows], 0.4, label="whole box")
ax[1].set_xticks(list(pos)); ax[1].set_xticklabels(names); ax[1].set_ylabel("PSNR vs voxel reference (dB)")
ax[1].legend(fontsize=8)
fig.suptitle("Tets only in the region vs the whole box (region-only transfer function)")
fig.tight_layout()
fig.savefig(os.path.join(out, "regions.png"), dpi=100)
print(open(os.path.join(out, "regions.md")).read())
