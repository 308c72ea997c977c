"""vtkTetRayCastMapper ends its rays at opaque geometry already drawn (the depth buffer).

A 2 x 2 x 2 box of constant colour and opacity seen straight on (parallel projection), with an
opaque plane through its middle on the left third, one behind it in the middle third and none on the
right: each third must show its closed-form composite. Needs a display (skips with exit 77).
"""
import math
import os
import sys

if not os.environ.get("DISPLAY"):
    print("no DISPLAY: skipped (run under xvfb-run -a)")
    sys.exit(77)

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
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

colour = (1.0, 0.5, 0.2)
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
assert mapper.GetIntermixIntersectingGeometry() == 1
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)

ren = vtkRenderer()
ren.SetBackground(0, 0, 0)
ren.AddVolume(volume)
blue = (0.0, 0.0, 1.0)
for x0, x1, z in ((-1.5, -0.5, 0.0), (-0.5, 0.5, -2.0)):  # through the middle; behind the box
    plane = vtkPlaneSource()
    plane.SetOrigin(x0, -1.5, z)
    plane.SetPoint1(x1, -1.5, z)
    plane.SetPoint2(x0, 1.5, z)
    pm = vtkPolyDataMapper()
    pm.SetInputConnection(plane.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(pm)
    actor.GetProperty().SetColor(*blue)
    actor.GetProperty().LightingOff()
    ren.AddActor(actor)

W = H = 120
win = vtkRenderWindow()
win.SetOffScreenRendering(1)
win.SetSize(W, H)
win.AddRenderer(ren)
cam = ren.GetActiveCamera()
cam.ParallelProjectionOn()
cam.SetPosition(0, 0, 10)
cam.SetFocalPoint(0, 0, 0)
cam.SetViewUp(0, 1, 0)
cam.SetParallelScale(1.5)
ren.ResetCameraClippingRange()


def shown(width=W):
    """Renders the window and returns its RGB in [0, 1], row 0 at the bottom."""
    win.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(H, width, 3) / 255.0


def composite(thickness, behind):
    a = 1 - 0.5 ** thickness
    return np.array(colour) * a + (1 - a) * np.array(behind)


def third(img, x):
    """Mean colour of the middle of the third around world x (inside the box, away from edges)."""
    px = int((x / 1.5 + 1) / 2 * W)
    return img[H // 2 - 10:H // 2 + 10, px - 5:px + 5].reshape(-1, 3).mean(axis=0)


img = shown()
expect = {-0.75: composite(1, blue), 0.0: composite(2, blue), 0.75: composite(2, (0, 0, 0))}
for x, want in expect.items():
    got = third(img, x)
    print(f"x={x:+.2f}: shown {np.round(got, 3)}, closed form {np.round(want, 3)}")
    assert np.abs(got - want).max() < 3 / 255, (x, got, want)

# In the right half of a window twice as wide, beside a renderer whose opaque plane covers its
# whole (left) viewport, the depth read must be this viewport's: the same picture as before.
win.SetSize(2 * W, H)
ren.SetViewport(0.5, 0, 1, 1)
left = vtkRenderer()
left.SetViewport(0, 0, 0.5, 1)
cover = vtkPlaneSource()
cover.SetOrigin(-5, -5, 1.5)
cover.SetPoint1(5, -5, 1.5)
cover.SetPoint2(-5, 5, 1.5)
cm = vtkPolyDataMapper()
cm.SetInputConnection(cover.GetOutputPort())
ca = vtkActor()
ca.SetMapper(cm)
ca.GetProperty().SetColor(0, 1, 0)
ca.GetProperty().LightingOff()
left.AddActor(ca)
left.SetActiveCamera(cam)
win.AddRenderer(left)
wide = shown(2 * W)
right = wide[:, W:]
for x, want in expect.items():
    got = third(right, x)
    print(f"right viewport x={x:+.2f}: shown {np.round(got, 3)}, closed form {np.round(want, 3)}")
    assert np.abs(got - want).max() < 3 / 255, (x, got, want)
assert np.abs(wide[H // 2, W // 2] - (0, 1, 0)).max() < 3 / 255, "the left renderer's plane"
win.RemoveRenderer(left)
ren.SetViewport(0, 0, 1, 1)
win.SetSize(W, H)

# Without intermixing the whole box is drawn over the plane in its middle (VTK's behaviour then).
mapper.IntermixIntersectingGeometryOff()
got = third(shown(), -0.75)
print(f"intermix off, x=-0.75: {np.round(got, 3)}")
assert np.abs(got - composite(2, blue)).max() < 3 / 255, got
print("ok")
