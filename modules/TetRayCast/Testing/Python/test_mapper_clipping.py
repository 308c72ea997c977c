"""vtkTetRayCastMapper honours the mapper's clipping planes, as VTK's volume mappers do.

A 2 x 2 x 2 box of constant colour and opacity seen straight on (parallel projection): each
clipping plane keeps the side its normal points to, in world coordinates (the vtkVolume moved),
and each pixel must show the closed-form composite of the thickness left. A plane through the
box's grid vertices (zero-volume pieces) must clip as well as one between them. It was ignored.
Needs a display (skips with exit 77).
"""
import os
import sys

if not os.environ.get("DISPLAY"):
    print("no DISPLAY: skipped (run under xvfb-run -a)")
    sys.exit(77)

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction, vtkPlane
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

import adaptivert

vtkObject.GlobalWarningDisplayOff()
image = vtkImageData()
image.SetDimensions(5, 5, 5)
image.SetOrigin(-1, -1, -1)
image.SetSpacing(0.5, 0.5, 0.5)
image.AllocateScalars(10, 1)  # VTK_FLOAT
image.GetPointData().GetScalars().Fill(1.0)
tri = vtkDataSetTriangleFilter()
tri.SetInputData(image)
tri.Update()

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
prop.SetScalarOpacityUnitDistance(1.0)  # opacity 0.5 per unit of thickness

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(tri.GetOutput())
mapper.AutoAdjustSampleDistancesOff()
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
ren = vtkRenderer()
ren.SetBackground(0, 0, 0)
ren.AddVolume(volume)
W = 120
win = vtkRenderWindow()
win.SetOffScreenRendering(1)
win.SetSize(W, W)
win.AddRenderer(ren)
cam = ren.GetActiveCamera()
cam.ParallelProjectionOn()
cam.SetPosition(0, 0, 10)
cam.SetFocalPoint(0, 0, 0)
cam.SetViewUp(0, 1, 0)
cam.SetParallelScale(2.0)
ren.ResetCameraClippingRange()


def shown():
    win.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(W, W, 3) / 255.0


def at(img, x, y=0.0):
    """Mean colour of a few pixels around world (x, y)."""
    px, py = int((x / 2 + 1) / 2 * W), int((y / 2 + 1) / 2 * W)
    return img[py - 2:py + 3, px - 2:px + 3].reshape(-1, 3).mean(axis=0)


def composite(thickness):
    return colour * (1 - 0.5 ** thickness)


plane = vtkPlane()
second = vtkPlane()
cases = [
    # (label, set-up, {world x: thickness shown there})
    ("no plane", lambda: None, {-0.5: 2, 0.5: 2}),
    ("x > 0, through grid vertices", lambda: (plane.SetOrigin(0, 0, 0), plane.SetNormal(1, 0, 0),
                                              mapper.AddClippingPlane(plane)), {-0.5: 0, 0.5: 2}),
    ("z > 0.1 (facing the camera)", lambda: (plane.SetOrigin(0, 0, 0.1), plane.SetNormal(0, 0, 1)), {-0.5: 0.9, 0.5: 0.9}),
    ("slab -0.3 < z < 0.1", lambda: (plane.SetNormal(0, 0, -1), second.SetOrigin(0, 0, -0.3), second.SetNormal(0, 0, 1),
                                     mapper.AddClippingPlane(second)), {-0.5: 0.4, 0.5: 0.4}),
    ("volume moved +1 in x, plane x > 1", lambda: (mapper.RemoveClippingPlane(second), plane.SetOrigin(1, 0, 0),
                                                   plane.SetNormal(1, 0, 0), volume.SetPosition(1, 0, 0)),
     {0.5: 0, 1.5: 2, -0.5: 0}),
    ("all clipped", lambda: plane.SetOrigin(5, 0, 0), {0.5: 0, 1.5: 0}),
    ("planes removed", lambda: mapper.RemoveAllClippingPlanes(), {0.5: 2, 1.5: 2, -0.5: 0}),
]
for label, setup, expect in cases:
    setup()
    img = shown()
    for x, thickness in expect.items():
        got, want = at(img, x), composite(thickness)
        print(f"{label}: x={x:+.1f} shown {np.round(got, 3)}, closed form {np.round(want, 3)}")
        assert np.abs(got - want).max() < 3 / 255, (label, x, got, want)
print("ok")
