"""vtkTetRayCastMapper honours the mapper's clipping planes, as VTK's volume mappers do.

A 2 x 2 x 2 box of constant colour and opacity seen straight on (parallel projection): each
clipping plane keeps the side its normal points to, in world coordinates (the vtkVolume moved),
and each pixel must show the closed-form composite of the thickness left. A plane through the
box's grid vertices (zero-volume pieces) must clip as well as one between them. It was ignored.
Needs a display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.vtkCommonCore import vtkObject
from vtkmodules.vtkCommonDataModel import vtkPlane

import adaptivert

vtkObject.GlobalWarningDisplayOff()
colour = np.array((1.0, 0.5, 0.2))
prop = constant_property(colour, 0.5, unit=1.0)  # opacity 0.5 per unit of thickness

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box_tets())
mapper.AutoAdjustSampleDistancesOff()
W = 120
volume, ren, win = offscreen_scene(mapper, prop, W, W)
look_down_z(ren, 2.0)


def shown():
    win.Render()
    return grab(win) / 255.0


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
