#!/usr/bin/python3
"""vtkTriangleGridLocator in a VTK pipeline: build it on a triangulated sphere, shoot lines at
the sphere, and check the hits against the analytic answer and against VTK's own
vtkModifiedBSPTree.

    /usr/bin/python3 locator_query.py
"""
import math
import random

import adaptivert
from vtkmodules.vtkCommonCore import vtkIdList, mutable
from vtkmodules.vtkFiltersFlowPaths import vtkModifiedBSPTree
from vtkmodules.vtkFiltersSources import vtkSphereSource

RADIUS, RES = 2.0, 96
sphere = vtkSphereSource()
sphere.SetRadius(RADIUS)
sphere.SetThetaResolution(RES)
sphere.SetPhiResolution(RES)
sphere.Update()
surface = sphere.GetOutput()

locator = adaptivert.vtkTriangleGridLocator()
locator.SetDataSet(surface)
locator.BuildLocator()
print(f"locator over {locator.GetNumberOfTriangles()} triangles")

bsp = vtkModifiedBSPTree()
bsp.SetDataSet(surface)
bsp.BuildLocator()

# Every facet point lies within the facet's angular diagonal of a vertex on the sphere, so the
# tessellation is inside the sphere by at most R (1 - cos(diagonal)).
diagonal = math.hypot(2 * math.pi / RES, math.pi / (RES - 1))
chord_error = RADIUS * (1 - math.cos(diagonal))
rng = random.Random(7)
worst, agree = 0.0, 0
N = 2000
for _ in range(N):
    # A line from 10 units away through a random point inside the sphere's core.
    d = [rng.gauss(0, 1) for _ in range(3)]
    n = math.sqrt(sum(c * c for c in d))
    d = [c / n for c in d]
    target = [rng.uniform(-0.5, 0.5) for _ in range(3)]
    p1 = [target[i] - 10 * d[i] for i in range(3)]
    p2 = [target[i] + 10 * d[i] for i in range(3)]
    t, x, pc, sub_id, cell = mutable(0.0), [0.0] * 3, [0.0] * 3, mutable(0), mutable(0)
    hit = locator.IntersectWithLine(p1, p2, 1e-9, t, x, pc, sub_id, cell)
    assert hit, "a line through the core must hit the sphere"
    r = math.sqrt(sum(c * c for c in x))
    worst = max(worst, abs(r - RADIUS))
    assert RADIUS - chord_error - 1e-9 <= r <= RADIUS + 1e-9, (r, RADIUS, chord_error)
    t2, x2, pc2, sub2, cell2 = mutable(0.0), [0.0] * 3, [0.0] * 3, mutable(0), mutable(0)
    bsp.IntersectWithLine(p1, p2, 1e-9, t2, x2, pc2, sub2, cell2)
    agree += abs(float(t) - float(t2)) < 1e-7
    cells = vtkIdList()
    locator.FindCellsAlongLine(p1, p2, 1e-9, cells)
    assert cells.GetNumberOfIds() >= 2, "a line through a closed surface crosses it at least twice"

print(f"{N} lines: every hit within {worst:.2e} of the radius (bound {chord_error:.2e}); "
      f"{agree}/{N} hit distances equal vtkModifiedBSPTree's")
assert agree >= N - 2, "the closest hit should agree with VTK's locator (edge ties aside)"
