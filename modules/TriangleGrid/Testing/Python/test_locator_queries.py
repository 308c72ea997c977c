"""vtkTriangleGridLocator as a drop-in VTK cell locator, from Python.

vtkCellPicker.AddLocator: the same picks (cell, position) with our locator as without any locator
(the picker then intersects every cell itself), on am_underworks and a sphere. And the point queries
through their wrapped overloads: FindClosestPoint equal to vtkStaticCellLocator's, within a radius,
FindCellsWithinBounds, FindCell.
"""
import math
import os
import random

import adaptivert
from vtkmodules.vtkCommonCore import reference, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkGenericCell, vtkStaticCellLocator
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCellPicker, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)

Loc = adaptivert.vtkTriangleGridLocator


def underworks():
    r = vtkPLYReader()
    r.SetFileName(os.path.join(os.environ["ART_SOURCE_DIR"], "data", "am_underworks.ply"))
    r.Update()
    return r.GetOutput()


def sphere():
    s = vtkSphereSource()
    s.SetCenter(0.5, -1.0, 2.0)
    s.SetRadius(3.0)
    s.SetThetaResolution(48)
    s.SetPhiResolution(36)
    s.Update()
    return s.GetOutput()


def picks(pd, locator, n, seed):
    """(cell, position) of n picks over the window, with `locator` added to the picker (or none)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(pd)
    actor = vtkActor()
    actor.SetMapper(mapper)
    ren = vtkRenderer()
    ren.AddActor(actor)
    win = vtkRenderWindow()  # never rendered: picking needs only the camera and the window size
    win.AddRenderer(ren)
    win.SetSize(160, 120)
    ren.ResetCamera()
    ren.GetActiveCamera().Azimuth(30)
    ren.GetActiveCamera().Elevation(20)
    ren.ResetCameraClippingRange()
    picker = vtkCellPicker()
    picker.SetTolerance(0.0)
    if locator is not None:
        picker.AddLocator(locator)
    rng = random.Random(seed)
    out = []
    for _ in range(n):
        x, y = rng.uniform(0, 159), rng.uniform(0, 119)
        hit = picker.Pick(x, y, 0, ren)
        out.append((hit, picker.GetCellId(), picker.GetPickPosition()))
    return out


for name, pd in (("am_underworks", underworks()), ("sphere", sphere())):
    diag = math.sqrt(pd.GetLength() ** 2)
    for kind in (Loc.BRUTE_FORCE, Loc.UNIFORM_GRID, Loc.RECURSIVE_GRID, Loc.OCTREE):
        loc = Loc()
        loc.SetDataSet(pd)
        loc.SetAcceleratorType(kind)
        loc.BuildLocator()
        plain = picks(pd, None, 300, 1)
        ours = picks(pd, loc, 300, 1)
        hits = sum(1 for h, _, _ in plain if h)
        assert hits > 50, (name, hits)
        for (h0, c0, p0), (h1, c1, p1) in zip(plain, ours):
            assert h0 == h1, (name, kind, h0, h1)
            if h0:
                # Same cell, unless the ray passes through an edge the two triangles share.
                assert math.dist(p0, p1) <= 1e-6 * diag, (name, kind, p0, p1)
                assert c0 == c1 or math.dist(p0, p1) <= 1e-9 * diag, (name, kind, c0, c1)

        # Point queries against vtkStaticCellLocator through the wrapped overloads.
        ref = vtkStaticCellLocator()
        ref.SetDataSet(pd)
        ref.BuildLocator()
        b = pd.GetBounds()
        rng = random.Random(kind)
        cell = vtkGenericCell()
        for i in range(400):
            x = [rng.uniform(b[0] - 0.3 * diag, b[1] + 0.3 * diag), rng.uniform(b[2] - 0.3 * diag, b[3] + 0.3 * diag),
                 rng.uniform(b[4] - 0.3 * diag, b[5] + 0.3 * diag)]
            cp, cpr = [0.0] * 3, [0.0] * 3
            cid, sub, d2 = reference(0), reference(0), reference(0.0)
            cidr, subr, d2r = reference(0), reference(0), reference(0.0)
            loc.FindClosestPoint(x, cp, cid, sub, d2)
            ref.FindClosestPoint(x, cpr, cell, cidr, subr, d2r)
            d, dr = math.sqrt(float(d2)), math.sqrt(float(d2r))
            assert abs(d - dr) <= 1e-9 * max(dr, 1e-3 * diag), (name, kind, x, d, dr)
            assert math.dist(cp, cpr) <= 1e-6 * diag or int(cid) != int(cidr)
            inside = reference(0)
            assert loc.FindClosestPointWithinRadius(x, 1.001 * d + 1e-12, cp, cell, cid, sub, d2, inside) == 1
            assert loc.FindClosestPointWithinRadius(x, 0.999 * d, cp, cell, cid, sub, d2, inside) == 0
        # Cells within a box around a surface point: non-empty, every listed cell touches the box.
        ids = vtkIdList()
        p = pd.GetPoint(pd.GetNumberOfPoints() // 2)
        h = 0.02 * diag
        box = [p[0] - h, p[0] + h, p[1] - h, p[1] + h, p[2] - h, p[2] + h]
        loc.FindCellsWithinBounds(box, ids)
        assert ids.GetNumberOfIds() > 0
        for k in range(ids.GetNumberOfIds()):
            cp = [0.0] * 3
            cid, sub, d2 = reference(0), reference(0), reference(0.0)
            c = [(box[0] + box[1]) / 2, (box[2] + box[3]) / 2, (box[4] + box[5]) / 2]
            pd.GetCell(ids.GetId(k), cell)
            cb = cell.GetBounds()
            assert all(cb[2 * a] <= box[2 * a + 1] and cb[2 * a + 1] >= box[2 * a] for a in range(3))
        # FindCell at a surface point: the cell that holds it, with weights summing to 1.
        pc, w = [0.0] * 3, [0.0] * 3
        x = list(pd.GetPoint(0))
        found = loc.FindCell(x, (1e-6 * diag) ** 2, cell, pc, w)
        assert found >= 0 and abs(sum(w) - 1) < 1e-9, (found, w)
    # The picker does consult the locator: one whose structure was built on a shifted copy (and kept
    # by UseExistingSearchStructure when pointed at the real data) picks differently.
    shifted = type(pd)()
    shifted.DeepCopy(pd)
    pts = shifted.GetPoints()
    for i in range(pts.GetNumberOfPoints()):
        q = pts.GetPoint(i)
        pts.SetPoint(i, q[0] + 0.25 * diag, q[1], q[2])
    stale = Loc()
    stale.SetDataSet(shifted)
    stale.BuildLocator()
    stale.UseExistingSearchStructureOn()
    stale.SetDataSet(pd)
    differ = sum(1 for a, b in zip(picks(pd, None, 100, 2), picks(pd, stale, 100, 2)) if a[0] != b[0] or a[1] != b[1])
    assert differ > 10, (name, differ)
    print(name, "ok")
