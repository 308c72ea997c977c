"""vtkTetRayCastMapper skips ghost cells (DUPLICATECELL in vtkGhostType), as VTK's mappers do.

In a parallel pipeline each piece carries copies of its neighbours' boundary cells, marked as
ghosts, which their own piece draws. A 2 x 2 x 2 box of constant colour and opacity, its left half
repeated as marked ghosts, must show the closed-form composite of the box once on both sides; the
ghosts overlapped the cells they copy and the mapper refused the mesh. Needs a display (skips
with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, messages, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.vtkCommonCore import vtkIdList, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes, vtkUnstructuredGrid

import adaptivert

box = box_tets()

piece = vtkUnstructuredGrid()
piece.SetPoints(box.GetPoints())
piece.GetPointData().ShallowCopy(box.GetPointData())
marks = vtkUnsignedCharArray()
marks.SetName(vtkDataSetAttributes.GhostArrayName())
ids = vtkIdList()
for ghost in (0, 1):
    for c in range(box.GetNumberOfCells()):
        b = box.GetCell(c).GetBounds()
        if ghost and (b[0] + b[1]) / 2 > 0:
            continue
        box.GetCellPoints(c, ids)
        piece.InsertNextCell(box.GetCellType(c), ids)
        marks.InsertNextValue(vtkDataSetAttributes.DUPLICATECELL if ghost else 0)
piece.GetCellData().AddArray(marks)
assert piece.GetNumberOfCells() == box.GetNumberOfCells() * 3 // 2

colour = np.array((1.0, 0.5, 0.2))
prop = constant_property(colour, 0.5, unit=1.0)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(piece)
mapper.AutoAdjustSampleDistancesOff()
errors = messages(mapper)
W = 80
volume, ren, win = offscreen_scene(mapper, prop, W, W)
look_down_z(ren, 1.5)
win.Render()
img = grab(win) / 255.0
assert not errors, errors
want = colour * (1 - 0.5 ** 2)
for x in (-0.5, 0.5):
    px = int((x / 1.5 + 1) / 2 * W)
    got = img[W // 2 - 3:W // 2 + 3, px - 3:px + 3].reshape(-1, 3).mean(axis=0)
    print(f"x={x:+.1f}: shown {np.round(got, 3)}, closed form {np.round(want, 3)}")
    assert np.abs(got - want).max() < 3 / 255, (x, got, want)
print("ok")
