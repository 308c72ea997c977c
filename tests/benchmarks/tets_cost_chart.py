"""Chart of the caster's instructions per tet crossed, one bar per commit of the per-tet work
(tets-results/tets-cost.json, callgrind counts of one frame), with the wall clock's ns per tet
of the first and last build as measured side by side."""
import json
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

data = json.load(open(sys.argv[1]))
rows = data["rows"]
n = data["tets_crossed"]
per = [r["instructions"] / n for r in rows]
fig, ax = plt.subplots(figsize=(9, 5))
bars = ax.barh(range(len(rows)), per, color="#4e79a7")
for i, (b, v) in enumerate(zip(bars, per)):
    ax.text(v + 5, i, f"{v:.0f}", va="center")
ax.set_yticks(range(len(rows)))
ax.set_yticklabels([f'{r["step"]} ({r["commit"]})' for r in rows])
ax.invert_yaxis()
ax.set_xlim(0, max(per) * 1.15)
ax.set_xlabel("instructions per tet crossed (callgrind, TetRayCaster::Render inclusive)")
w = data.get("wall_clock")
note = ""
if w:
    note = (f'\nwall clock ({w["rounds"]} rounds, {w["threads"]} thread, load {w["load_average"]}): '
            f'{w["main"]["ns_per_tet"]} ns/tet before, {w["this"]["ns_per_tet"]} ns/tet after')
ax.set_title(textwrap.fill(data["frame"], 75) + note, fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)
