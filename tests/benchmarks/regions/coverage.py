#!/usr/bin/python3
"""Which of a region's voxels a region mesh leaves out: `coverage.py VOLUME MESH LO HI [OUT.json]`
locates every voxel whose value lies in [LO, HI] in the mesh (the voxel's centre, through the
mesh's IndexToWorld) and breaks the ones outside down by how deep they lie in the region (0: a
6-neighbour is outside it) and by value. Prints a table; writes the figures as JSON and, beside
it, a chart (OUT.png)."""
import json
import sys

import numpy as np
import vtk
from vtk.util import numpy_support as ns

volume, mesh_file, lo, hi = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
reader = vtk.vtkMetaImageReader() if volume.endswith((".mha", ".mhd")) else vtk.vtkNIFTIImageReader()
reader.SetFileName(volume)
reader.Update()
image = reader.GetOutput()
d = image.GetDimensions()
v = ns.vtk_to_numpy(image.GetPointData().GetScalars()).reshape(d[2], d[1], d[0]).astype(float)
mr = vtk.vtkXMLUnstructuredGridReader()
mr.SetFileName(mesh_file)
mr.Update()
mesh = mr.GetOutput()
m = mesh.GetFieldData().GetAbstractArray("IndexToWorld")
M = np.array([float(m.GetVariantValue(i).ToString()) for i in range(16)]).reshape(4, 4)
inside = (v >= lo) & (v <= hi)
k, j, i = np.nonzero(inside)
world = np.stack([i, j, k, np.ones_like(i)], 1).astype(float) @ M.T
locator = vtk.vtkStaticCellLocator()
locator.SetDataSet(mesh)
locator.BuildLocator()
cell, pc, w = vtk.vtkGenericCell(), [0.0] * 3, [0.0] * 8
lost = np.array([locator.FindCell(p[:3], 1e-9, cell, pc, w) < 0 for p in world])
# Depth: 6-neighbour erosions survived (0: on the region's surface), up to 3.
depth, kept = np.zeros(v.shape, int), inside.copy()
for s in range(1, 4):
    e = kept.copy()
    for axis in range(3):
        e &= np.roll(kept, 1, axis) & np.roll(kept, -1, axis)
    kept = e
    depth[kept] = s
dv, vv = depth[k, j, i], v[k, j, i]
span = hi - lo
edges = [lo, lo + 0.05 * span, lo + 0.12 * span, lo + 0.3 * span, hi + 1e-9]
out = dict(volume=volume, mesh=mesh_file, region=[lo, hi], voxels=int(inside.sum()), lost=int(lost.sum()),
           covered_percent=100.0 * (1 - lost.mean()),
           by_depth=[dict(depth=s, voxels=int((dv == s).sum()), lost=int(lost[dv == s].sum())) for s in range(4)],
           by_value=[dict(low=a, high=b, voxels=int(((vv >= a) & (vv < b)).sum()),
                          lost=int(lost[(vv >= a) & (vv < b)].sum())) for a, b in zip(edges, edges[1:])])
print("%s: %d of %d region voxels outside the mesh (%.2f%% covered)" % (mesh_file, out["lost"], out["voxels"],
                                                                      out["covered_percent"]))
for r in out["by_depth"]:
    print("  depth %d: %7d voxels, %5.1f%% lost" % (r["depth"], r["voxels"], 100.0 * r["lost"] / max(r["voxels"], 1)))
for r in out["by_value"]:
    print("  value %7.1f .. %7.1f: %7d voxels, %5.1f%% lost" % (r["low"], r["high"], r["voxels"],
                                                              100.0 * r["lost"] / max(r["voxels"], 1)))
if len(sys.argv) > 5:
    json.dump(out, open(sys.argv[5], "w"), indent=1)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.4))
    ax[0].bar([str(r["depth"]) for r in out["by_depth"]], [100.0 * r["lost"] / max(r["voxels"], 1) for r in out["by_depth"]])
    ax[0].set_xlabel("depth in the region (6-neighbour erosions; 0 = on its surface)")
    ax[0].set_ylabel("% of those voxels outside the mesh")
    ax[1].bar(["%.0f-%.0f" % (r["low"], r["high"]) for r in out["by_value"]],
              [100.0 * r["lost"] / max(r["voxels"], 1) for r in out["by_value"]], color="tab:orange")
    ax[1].set_xlabel("voxel value")
    fig.suptitle("%.2f%% of %d region voxels inside the mesh" % (out["covered_percent"], out["voxels"]))
    fig.tight_layout()
    fig.savefig(sys.argv[5].rsplit(".", 1)[0] + ".png", dpi=80)
