"""vtkTetRayCastMapper draws a grey colour function (vtkVolumeProperty.SetColor with a
vtkPiecewiseFunction, one colour channel) as VTK's mappers do, and leaves the property as it was.

It read the property's RGB function instead, which VTK fills with its default black-to-white ramp
over 0..1024 when none is set: a box of value 1 in grey 0.8 drew black, and the property was
switched to three channels, so VTK's own mappers lost the grey too. Needs a display (skips with
exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingCore import vtkVolumeProperty

import adaptivert

box = box_tets(points=5, origin=(-1, -1, -1), spacing=0.5, value=1.0)


def grey_property(x0, g0, x1, g1, midpoint=0.5):
    grey = vtkPiecewiseFunction()
    grey.AddPoint(x0, g0, midpoint, 0.0)  # a node's midpoint bends the segment after it
    grey.AddPoint(x1, g1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0, 0.5)
    opacity.AddPoint(2, 0.5)
    prop = vtkVolumeProperty()
    prop.SetColor(grey)
    prop.SetScalarOpacity(opacity)
    return prop


mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box)
mapper.AutoAdjustSampleDistancesOff()
volume, ren, win = offscreen_scene(mapper, grey_property(0, 0.8, 2, 0.8), 40, 30)
look_down_z(ren, 2.0)


def image(prop):
    volume.SetProperty(prop)
    win.Render()
    last = mapper.GetLastImage()
    w, h = last.GetDimensions()[:2]
    return vtk_to_numpy(last.GetPointData().GetScalars()).reshape(h, w, 4).copy()


for grey, (x0, g0, x1, g1, mid), rgb in [
    ("constant 0.8", (0, 0.8, 2, 0.8, 0.5), (0.8, 0.8, 0.8)),
    ("ramp 0.2 .. 0.6 over 0 .. 2", (0, 0.2, 2, 0.6, 0.5), (0.4, 0.4, 0.4)),
    ("ramp with midpoint 0.25", (0, 0.0, 2, 1.0, 0.25), (0.5, 0.5, 0.5)),
]:
    prop = grey_property(x0, g0, x1, g1, mid)
    got = image(prop)
    assert prop.GetColorChannels() == 1, f"{grey}: the property was switched to {prop.GetColorChannels()} channels"
    covered = got[..., 3] > 0.1
    assert covered.mean() > 0.2, f"{grey}: {covered.mean():.0%} of the pixels covered"
    # Premultiplied: colour / alpha is the grey at value 1.
    ratio = got[covered][:, :3] / got[covered][:, 3:4]
    # The same function as an RGB property of equal channels draws the same image (a midpoint
    # bends both alike; constant_property is linear, so it stands for the two linear cases only).
    if mid == 0.5:
        same = image(constant_property(rgb, 0.5, unit=prop.GetScalarOpacityUnitDistance()))
        print(f"{grey}: colour/alpha {ratio.mean(0)}, vs RGB property max difference {np.abs(same - got).max():.2e}")
        assert np.abs(same - got).max() < 1e-5, grey
        assert np.allclose(ratio, rgb[0], atol=2e-3), (grey, ratio.min(), ratio.max())
    else:
        # Midpoint 0.25 bends the ramp above its straight line (0.5 at value 1), to VTK's value.
        want = prop.GetGrayTransferFunction().GetValue(1.0)
        print(f"{grey}: colour/alpha {ratio.mean(0)}, VTK's grey at 1: {want:.4f}")
        assert want > 0.55 and np.allclose(ratio, want, atol=5e-3), (grey, want, ratio.min(), ratio.max())

# The window shows it too (premultiplied over black: 0.8 * alpha).
volume.SetProperty(grey_property(0, 0.8, 2, 0.8))
win.Render()
shown = grab(win).astype(float)
centre = shown[15, 20]
print(f"window centre pixel {centre}")
assert centre.min() > 60 and np.ptp(centre) < 3, centre
print("ok")
