"""vtkTetRayCastMapper follows the camera's window centre (vtkCamera.SetWindowCenter), its view
shear and each eye of a stereo render, as VTK's own ray cast mappers do.

The window centre was ignored: the volume stayed in the middle of the viewport while opaque
geometry moved, and vtkRenderLargeImage (the tiling behind VTK's and ParaView's screenshots larger
than the window), which renders each tile through a shifted window centre, repeated the whole
volume in every tile. Here a box seen in perspective from off its axes must fill the same pixels as
the same box drawn as opaque geometry with a shifted centre (perspective and parallel), and a
large image at magnification 2 must match one render at twice the size. In a stereo window
(left and right eye) the volume drew the same picture for both eyes, with no depth, while opaque
geometry was drawn from each eye (VTK shears each eye's projection). Needs a display (skips with
exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkFiltersHybrid import vtkRenderLargeImage
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

import adaptivert

box = box_tets()
# One window for every render, its renderer swapped: a window per render (each an X connection,
# opened in quick succession) lost the X server's connection now and then under ctest.
WINDOW = None


def scene(width, height, opaque=False, parallel=False, centre=(0.0, 0.0), stereo=None, shear=None):
    global WINDOW
    mapper = adaptivert.vtkTetRayCastMapper()
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetInputData(box)
    volume, ren, win = offscreen_scene(mapper, constant_property((1.0, 0.5, 0.2), 0.5), width, height)
    win.RemoveRenderer(ren)
    if WINDOW is None:
        WINDOW = win
        WINDOW.StereoCapableWindowOn()
    win = WINDOW
    win.GetRenderers().RemoveAllItems()
    win.AddRenderer(ren)
    win.SetSize(width, height)
    win.StereoRenderOff()
    if opaque:
        ren.RemoveVolume(volume)
        surface = vtkGeometryFilter()
        surface.SetInputData(box)
        pm = vtkPolyDataMapper()
        pm.SetInputConnection(surface.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(pm)
        actor.GetProperty().LightingOff()
        ren.AddActor(actor)
    cam = ren.GetActiveCamera()
    cam.SetPosition(3, 2, 6)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 1, 0)
    cam.SetParallelProjection(parallel)
    ren.ResetCamera()
    cam.SetWindowCenter(*centre)
    ren.ResetCameraClippingRange()
    if shear is not None:
        cam.SetViewShear(*shear)
    if stereo is not None:
        win.SetStereoType(stereo)
        win.StereoRenderOn()
        cam.SetEyeAngle(40)
    return ren, win


def covered(img):
    return img.max(axis=2) > 8


def covered_in(**options):
    """The covered pixels of one render."""
    ren, win = scene(W, H, **options)
    win.Render()
    return covered(grab(win))


W, H = 160, 120
for parallel in (False, True):
    for centre in ((0.5, 0.0), (-0.3, 0.4)):
        volume = covered_in(parallel=parallel, centre=centre)
        truth = covered_in(opaque=True, parallel=parallel, centre=centre)
        wrong = int((volume != truth).sum())
        print(f"parallel {parallel}, window centre {centre}: {wrong} pixels differ from the opaque box "
              f"({int(truth.sum())} covered)")
        # Only the silhouette's edge may differ (rays through pixel centres against rasterisation).
        assert wrong < 0.05 * truth.sum(), (parallel, centre, wrong)

from vtkmodules.vtkRenderingCore import VTK_STEREO_LEFT, VTK_STEREO_RIGHT

eyes = {}
for name, stereo in (("left", VTK_STEREO_LEFT), ("right", VTK_STEREO_RIGHT)):
    volume = covered_in(stereo=stereo)
    truth = covered_in(opaque=True, stereo=stereo)
    eyes[name] = truth
    wrong = int((volume != truth).sum())
    print(f"stereo, {name} eye: {wrong} pixels differ from the opaque box ({int(truth.sum())} covered)")
    assert wrong < 0.05 * truth.sum(), (name, wrong)
# The eyes see differently (else the check above could not tell a volume that ignores them).
assert (eyes["left"] != eyes["right"]).sum() > 0.1 * eyes["left"].sum()
# A sheared view (the volume stayed unsheared, with a warning), alone and with a stereo eye.
plain = covered_in(opaque=True)
for shear, stereo in (((0.3, -0.2, 1.0), None), ((0.2, 0.1, 0.5), VTK_STEREO_RIGHT)):
    volume = covered_in(shear=shear, stereo=stereo)
    truth = covered_in(opaque=True, shear=shear, stereo=stereo)
    wrong = int((volume != truth).sum())
    print(f"view shear {shear}, stereo {stereo}: {wrong} pixels differ from the opaque box ({int(truth.sum())} covered)")
    assert wrong < 0.05 * truth.sum(), (shear, stereo, wrong)
    assert (truth != plain).sum() > 0.1 * plain.sum()

ren, win = scene(W, H)
win.Render()
large = vtkRenderLargeImage()
large.SetInput(ren)
large.SetMagnification(2)
large.Update()
out = large.GetOutput()
w, h = out.GetDimensions()[:2]
tiled = vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, -1)[..., :3].astype(float)
ren2, win2 = scene(2 * W, 2 * H)
win2.Render()
direct = grab(win2).astype(float)
diff = np.abs(tiled - direct).mean()
print(f"magnification 2: mean difference {diff:.2f} levels from one {2 * W} x {2 * H} render")
assert (w, h) == (2 * W, 2 * H)
assert diff < 2.0, diff  # 75 levels when every tile drew the whole box
