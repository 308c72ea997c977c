"""vtkTriangleGridLocator from Python: closest and all hits on a sphere against analytic distances."""
import math
import sys

import adaptivert
from vtkmodules.vtkCommonCore import reference, vtkIdList, vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
from vtkmodules.vtkFiltersSources import vtkSphereSource

R = 2.0
src = vtkSphereSource()
src.SetRadius(R)
src.SetCenter(1.0, -2.0, 3.0)
src.SetThetaResolution(96)
src.SetPhiResolution(96)
src.Update()
sphere = src.GetOutput()
# A polygonal sphere lies inside the true one by at most the chord sag of its largest facet.
sag = R * (1 - math.cos(math.pi / 96))

for kind in (adaptivert.vtkTriangleGridLocator.UNIFORM_GRID,
             adaptivert.vtkTriangleGridLocator.RECURSIVE_GRID,
             adaptivert.vtkTriangleGridLocator.OCTREE):
    loc = adaptivert.vtkTriangleGridLocator()
    loc.SetDataSet(sphere)
    loc.SetAcceleratorType(kind)
    loc.BuildLocator()
    assert loc.GetNumberOfTriangles() == sphere.GetNumberOfCells(), loc.GetNumberOfTriangles()
    for d in ((1, 0, 0), (0, -1, 0), (0.3, 0.4, -0.5), (-1, -1, 1)):
        n = math.sqrt(sum(c * c for c in d))
        u = [c / n for c in d]
        p1 = [1.0 + 10 * u[0], -2.0 + 10 * u[1], 3.0 + 10 * u[2]]
        p2 = [1.0 - 10 * u[0], -2.0 - 10 * u[1], 3.0 - 10 * u[2]]
        t = reference(0.0)
        sub = reference(0)
        cell = reference(0)
        x = [0.0, 0.0, 0.0]
        pc = [0.0, 0.0, 0.0]
        assert loc.IntersectWithLine(p1, p2, 0.0, t, x, pc, sub, cell) == 1
        dist = float(t) * 20.0  # |p2 - p1| = 20
        assert 10 - R <= dist <= 10 - R + sag + 1e-9, (kind, d, dist)
        r = math.sqrt((x[0] - 1) ** 2 + (x[1] + 2) ** 2 + (x[2] - 3) ** 2)
        assert R - sag - 1e-9 <= r <= R + 1e-9, r
        assert 0 <= int(cell) < sphere.GetNumberOfCells()
        # All hits: entry and exit, sorted, symmetric about the centre; p1 is outside.
        pts = vtkPoints()
        ids = vtkIdList()
        assert loc.IntersectWithLine(p1, p2, pts, ids) == 1
        assert pts.GetNumberOfPoints() == 2 and ids.GetNumberOfIds() == 2, pts.GetNumberOfPoints()
        a, b = pts.GetPoint(0), pts.GetPoint(1)
        da = math.dist(a, p1)
        db = math.dist(b, p1)
        assert da < db and abs(da - dist) < 1e-5  # vtkPoints stores float
        assert 10 + R - sag - 1e-5 <= db <= 10 + R + 1e-5, db
        # From the centre outwards: one hit, and the start point is inside (-1).
        assert loc.IntersectWithLine([1.0, -2.0, 3.0], p1, pts, ids) == -1
        assert pts.GetNumberOfPoints() == 1
        cells = vtkIdList()
        loc.FindCellsAlongLine(p1, p2, 0.0, cells)
        assert ids.GetId(0) in [cells.GetId(i) for i in range(cells.GetNumberOfIds())]
    # A miss returns 0 and leaves cellId -1.
    cell = reference(5)
    assert loc.IntersectWithLine([10, 10, 10], [11, 10, 10], 0.0, reference(0.0), [0, 0, 0], [0, 0, 0],
                                 reference(0), cell) == 0
    assert int(cell) == -1

# The same sphere 2.5e7 units out (survey coordinates, double points): the engine stores floats,
# so it takes the scene's coordinates from its centre; hits keep their distances.
far = vtkSphereSource()
far.SetRadius(R)
C = (2.5e7 + 0.7, -1.0e7 + 0.3, 4.0e6 + 0.1)
far.SetCenter(*C)
far.SetThetaResolution(96)
far.SetPhiResolution(96)
far.SetOutputPointsPrecision(vtkAlgorithm.DOUBLE_PRECISION)
far.Update()
loc = adaptivert.vtkTriangleGridLocator()
loc.SetDataSet(far.GetOutput())
loc.BuildLocator()
assert loc.GetNumberOfTriangles() == far.GetOutput().GetNumberOfCells(), loc.GetNumberOfTriangles()
u = [0.6, -0.48, 0.64]  # unit, off the axes
p1 = [C[k] + 10 * u[k] for k in range(3)]
p2 = [C[k] - 10 * u[k] for k in range(3)]
t = reference(0.0)
x = [0.0, 0.0, 0.0]
assert loc.IntersectWithLine(p1, p2, 0.0, t, x, [0.0, 0.0, 0.0], reference(0), reference(0)) == 1
dist = float(t) * 20.0
assert 10 - R <= dist <= 10 - R + sag + 1e-6, dist
assert abs(math.dist(x, C) - R) <= sag + 1e-6, math.dist(x, C)

print("ok", file=sys.stderr)
