"""vtkTetRayCastMapper honours a vtkVolume matrix that is no similarity (SetScale(1, 1, 3), as
users stretch thick slices; a shear), as VTK's own mappers do.

A 2 x 2 x 2 box of constant colour and opacity, scaled to 2 x 2 x 6 in the world and seen with a
parallel camera along x (2 units thick, 6 tall) and along z (6 thick): each view must show the box's
world silhouette and the closed-form composite of its world thickness. The rays were cast as if the
scale were uniform (a warning said so): the view along x showed a 2.9-unit square. A mirror
(negative scale) must be drawn where it is, with lengths in data units as for a positive scale.
Needs a display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.vtkCommonMath import vtkMatrix4x4

import adaptivert

colour = np.array((1.0, 0.5, 0.2))
prop = constant_property(colour, 0.3, unit=1.0)  # opacity 0.3 per world unit

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box_tets())
mapper.AutoAdjustSampleDistancesOff()
W = 100
volume, ren, win = offscreen_scene(mapper, prop, W, W)
volume.SetScale(1, 1, 3)
cam = ren.GetActiveCamera()
cam.ParallelProjectionOn()
cam.SetParallelScale(4.0)  # the window shows 8 x 8 world units


def shown(position, up):
    cam.SetPosition(*position)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(*up)
    ren.ResetCameraClippingRange()
    win.Render()
    return grab(win) / 255.0


def composite(thickness):
    return colour * (1 - 0.7 ** thickness)


def extent(img):
    """Width and height (world units) of the drawn pixels."""
    drawn = img.max(axis=2) > 0.5 * img.max()  # half the peak: the drawn quad is filtered
    cols, rows = np.where(drawn.any(axis=0))[0], np.where(drawn.any(axis=1))[0]
    return (cols[-1] - cols[0] + 1) * 8.0 / W, (rows[-1] - rows[0] + 1) * 8.0 / W


def check(label, img, width, height, thickness):
    w, h = extent(img)
    got = img[W // 2 - 3:W // 2 + 3, W // 2 - 3:W // 2 + 3].reshape(-1, 3).mean(axis=0)
    want = composite(thickness)
    print(f"{label}: {w:.2f} x {h:.2f} world units (box {width} x {height}), centre {np.round(got, 3)}, "
          f"closed form {np.round(want, 3)}")
    assert abs(w - width) <= 0.2 and abs(h - height) <= 0.2, (label, w, h)
    assert np.abs(got - want).max() < 3 / 255, (label, got, want)


# Along -x with z up: y across (2), z up (6), 2 thick.
check("scale 1 1 3, along x", shown((10, 0, 0), (0, 0, 1)), 2, 6, 2)
# Along -z: x and y (2 x 2), 6 thick.
check("scale 1 1 3, along z", shown((0, 0, 10), (0, 1, 0)), 2, 2, 6)
# A mirror (negative scale) moved to x = 1..3 must be drawn there: the camera taken through the
# mirror drew it on the other side of the view (x = -3..-1). Lengths stay in data units, as for
# the same positive scale: SetScale(-2, 2, 2) and SetScale(2, 2, 2) show the same composite.
for sx, position in ((-1, 2), (-2, 1), (2, 1)):
    volume.SetScale(sx, abs(sx), abs(sx))
    volume.SetPosition(position, 0, 0)
    img = shown((0, 0, 10), (0, 1, 0))
    drawn = np.where((img.max(axis=2) > 0.5 * img.max()).any(axis=0))[0]
    left, right = drawn[0] * 8.0 / W - 4, (drawn[-1] + 1) * 8.0 / W - 4
    cx = int((position / 8.0 + 0.5) * W)
    got = img[W // 2 - 2:W // 2 + 3, cx - 2:cx + 3].reshape(-1, 3).mean(axis=0)
    want = composite(2)  # 2 data units thick
    print(f"scale {sx}, position {position}: x {left:.2f} .. {right:.2f}, centre {np.round(got, 3)}, "
          f"closed form {np.round(want, 3)}")
    assert abs(left - (position - abs(sx))) <= 0.2 and abs(right - (position + abs(sx))) <= 0.2, (sx, left, right)
    assert np.abs(got - want).max() < 3 / 255, (sx, got, want)
volume.SetPosition(0, 0, 0)
# A shear x += z (columns not orthogonal), seen along y: a parallelogram 2 high spanning x -2..2.
volume.SetScale(1, 1, 1)
shear = vtkMatrix4x4()
shear.SetElement(0, 2, 1.0)
volume.SetUserMatrix(shear)
img = shown((0, -10, 0), (0, 0, 1))
w, h = extent(img)
print(f"shear x += z, along y: {w:.2f} x {h:.2f}")
assert abs(w - 4) <= 0.2 and abs(h - 2) <= 0.2, (w, h)
print("ok")
