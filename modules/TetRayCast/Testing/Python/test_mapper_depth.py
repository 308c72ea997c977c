"""vtkTetRayCastMapper ends its rays at opaque geometry already drawn (the depth buffer).

A 2 x 2 x 2 box of constant colour and opacity seen straight on (parallel projection), with an
opaque plane through its middle on the left third, one behind it in the middle third and none on the
right: each third must show its closed-form composite. Needs a display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import adaptivert

colour = (1.0, 0.5, 0.2)
prop = constant_property(colour, 0.5, unit=1.0)  # opacity 0.5 per unit of thickness

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box_tets())
assert mapper.GetIntermixIntersectingGeometry() == 1
W = H = 120
volume, ren, win = offscreen_scene(mapper, prop, W, H)
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
cam = look_down_z(ren, 1.5)


def shown():
    """Renders the window and returns its RGB in [0, 1], row 0 at the bottom."""
    win.Render()
    return grab(win) / 255.0


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
wide = shown()
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
