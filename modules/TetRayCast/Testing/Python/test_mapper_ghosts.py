"""vtkTetRayCastMapper skips ghost cells (DUPLICATECELL in vtkGhostType), as VTK's mappers do.

In a parallel pipeline each piece carries copies of its neighbours' boundary cells, marked as
ghosts, which their own piece draws. A 2 x 2 x 2 box of constant colour and opacity, its left half
repeated as marked ghosts, must show the closed-form composite of the box once on both sides; the
ghosts overlapped the cells they copy and the mapper refused the mesh. Needs a display (skips
with exit 77).
"""
import os
import sys

if not os.environ.get("DISPLAY"):
    print("no DISPLAY: skipped (run under xvfb-run -a)")
    sys.exit(77)

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import (vtkDataSetAttributes, vtkImageData, vtkPiecewiseFunction,
                                           vtkUnstructuredGrid)
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import adaptivert

image = vtkImageData()
image.SetDimensions(5, 5, 5)
image.SetOrigin(-1, -1, -1)
image.SetSpacing(0.5, 0.5, 0.5)
image.AllocateScalars(10, 1)  # VTK_FLOAT
image.GetPointData().GetScalars().Fill(1.0)
tri = vtkDataSetTriangleFilter()
tri.SetInputData(image)
tri.Update()
box = tri.GetOutput()

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
ctf = vtkColorTransferFunction()
ctf.AddRGBPoint(0, *colour)
ctf.AddRGBPoint(2, *colour)
otf = vtkPiecewiseFunction()
otf.AddPoint(0, 0.5)
otf.AddPoint(2, 0.5)
prop = vtkVolumeProperty()
prop.SetColor(ctf)
prop.SetScalarOpacity(otf)
prop.SetScalarOpacityUnitDistance(1.0)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(piece)
mapper.AutoAdjustSampleDistancesOff()
errors = []


@calldata_type(VTK_STRING)
def on_error(obj, event, text):
    errors.append(text)


mapper.AddObserver(vtkCommand.ErrorEvent, on_error)
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
ren = vtkRenderer()
ren.SetBackground(0, 0, 0)
ren.AddVolume(volume)
W = 80
win = vtkRenderWindow()
win.SetOffScreenRendering(1)
win.SetSize(W, W)
win.AddRenderer(ren)
cam = ren.GetActiveCamera()
cam.ParallelProjectionOn()
cam.SetPosition(0, 0, 10)
cam.SetFocalPoint(0, 0, 0)
cam.SetViewUp(0, 1, 0)
cam.SetParallelScale(1.5)
ren.ResetCameraClippingRange()
win.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(win)
grab.SetInputBufferTypeToRGB()
grab.ReadFrontBufferOff()
grab.Update()
img = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(W, W, 3) / 255.0
assert not errors, errors
want = colour * (1 - 0.5 ** 2)
for x in (-0.5, 0.5):
    px = int((x / 1.5 + 1) / 2 * W)
    got = img[W // 2 - 3:W // 2 + 3, px - 3:px + 3].reshape(-1, 3).mean(axis=0)
    print(f"x={x:+.1f}: shown {np.round(got, 3)}, closed form {np.round(want, 3)}")
    assert np.abs(got - want).max() < 3 / 255, (x, got, want)
print("ok")
