#!/usr/bin/python3
"""Writes the meshing tests' inputs: a torus (R 1, r 0.4) as a closed PLY whose vertices lie on
it, the same with one triangle removed (3 open edges), two tori through each other (closed but
self-intersecting); a sphere of 1 (radius 10 voxels) in a box of 0, and two touching labelled
cubes (labels 1 and 2 meeting at z = 11.5) as MetaImages. cubes-labels.vtu is made from the last:
`adaptivert reduce cubes-24.mha cubes-labels.vtu --labels --tets 1000`. Then two labels side by
side with a ramp, and the CT head's tissue as labels; ct-tissue-values.vtu is made from those:
`adaptivert reduce ct-head-128-tissue.mha ct-tissue-values.vtu --labels --values
../../../data/ct-head-128.mha --tets 4000`."""
import math
import numpy as np
import vtk
from vtk.util import numpy_support as ns


def torus(nu, nv, shift=(0.0, 0.0, 0.0), R=1.0, r=0.4):
    pts = [((R + r * math.cos(2 * math.pi * j / nv)) * math.cos(2 * math.pi * i / nu) + shift[0],
            (R + r * math.cos(2 * math.pi * j / nv)) * math.sin(2 * math.pi * i / nu) + shift[1],
            r * math.sin(2 * math.pi * j / nv) + shift[2]) for i in range(nu) for j in range(nv)]
    idx = lambda i, j: (i % nu) * nv + (j % nv)
    tris = []
    for i in range(nu):
        for j in range(nv):
            tris += [(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)), (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1))]
    return pts, tris


def write_ply(name, pts, tris):
    with open(name, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(pts), len(tris)))
        for p in pts:
            f.write("%.7g %.7g %.7g\n" % p)
        for t in tris:
            f.write("3 %d %d %d\n" % t)


def write_mha(name, a, array):
    im = vtk.vtkImageData()
    im.SetDimensions(a.shape[2], a.shape[1], a.shape[0])
    v = ns.numpy_to_vtk(a.ravel(), deep=1)
    v.SetName(array)
    im.GetPointData().SetScalars(v)
    w = vtk.vtkMetaImageWriter()
    w.SetFileName(name)
    w.SetInputData(im)
    w.SetCompression(True)
    w.Write()


pts, tris = torus(48, 16)
write_ply("torus.ply", pts, tris)
write_ply("torus-open.ply", pts, tris[:7] + tris[8:])
a, ta = torus(24, 12)
b, tb = torus(24, 12, (1.0, 0.0, 0.1))
write_ply("tori-crossing.ply", a + b, ta + [(x + len(a), y + len(a), z + len(a)) for x, y, z in tb])

n, R = 32, 10.0
c = (n - 1) / 2
z, y, x = np.mgrid[0:n, 0:n, 0:n]
write_mha("sphere-32.mha", ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 <= R * R).astype(np.uint8), "sphere")
cubes = np.zeros((24, 24, 24), np.uint8)
cubes[4:12, 4:20, 4:20] = 1
cubes[12:20, 4:20, 4:20] = 2
write_mha("cubes-24.mha", cubes, "label")

# Two labels side by side (x < 12: 1, x >= 12: 2) over 4 .. 19 in y and z, and values that ramp
# along z (10 z): each label's colour must brighten with z in its own hue, and a region of the
# ramp is fitted exactly.
halves = np.zeros((24, 24, 24), np.uint8)
halves[4:20, 4:20, 4:12] = 1
halves[4:20, 4:20, 12:20] = 2
write_mha("halves-24.mha", halves, "label")
z, y, x = np.mgrid[0:24, 0:24, 0:24]
write_mha("halves-24-ramp.mha", (10.0 * z).astype(np.float32), "ramp")

# The CT head's tissue as labels: 1 skin and soft tissue (-400 .. 250 HU), 2 bone (above 250),
# from the project's data/ct-head-128.mha; `reduce --labels --values` carries the CT inside them.
r = vtk.vtkMetaImageReader()
r.SetFileName("../../../data/ct-head-128.mha")
r.Update()
ct = r.GetOutput()
hu = ns.vtk_to_numpy(ct.GetPointData().GetScalars()).reshape(ct.GetDimensions()[::-1])
tissue = np.where(hu >= 250, 2, np.where(hu >= -400, 1, 0)).astype(np.uint8)
im = vtk.vtkImageData()
im.CopyStructure(ct)
v = ns.numpy_to_vtk(tissue.ravel(), deep=1)
v.SetName("label")
im.GetPointData().SetScalars(v)
w = vtk.vtkMetaImageWriter()
w.SetFileName("ct-head-128-tissue.mha")
w.SetInputData(im)
w.SetCompression(True)
w.Write()
