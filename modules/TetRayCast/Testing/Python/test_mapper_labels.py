"""vtkTetRayCastMapper draws a label mesh (a cell array "label") label by label: by default the
selected point values inside each label, through the property's functions in the label's
categorical hue; VTK's per-label functions (SetLabelColor) where a label has them; each label in
one colour under LabelColoringToFlat; the property's functions alone under LabelColoringToOff.

A slab x in [-1, 1], y in [-0.5, 0.5], z in [-0.25, 0.25]: label 1 for x < 0, label 2 for x > 0,
values v = y (linear: every tet holds it exactly). Seen down z with a constant extinction, each
pixel's colour over its opacity is the colour function at the pixel's y, exactly. Needs a
display (skips with exit 77).
"""
from mapper_scene import look_down_z, messages, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty

import adaptivert

# The first three of the categorical palette (TransferFunction::CategoricalColour), label 1 and 2.
PALETTE = {1: (1.000, 0.498, 0.055), 2: (0.173, 0.627, 0.173)}


def slab():
    image = vtkImageData()
    image.SetDimensions(9, 5, 3)
    image.SetOrigin(-1, -0.5, -0.25)
    image.SetSpacing(0.25, 0.25, 0.25)
    tri = vtkDataSetTriangleFilter()
    tri.SetInputData(image)
    tri.Update()
    grid = tri.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    values = numpy_to_vtk(points[:, 1].astype(np.float32).copy(), deep=1)
    values.SetName("ramp")
    grid.GetPointData().SetScalars(values)
    label = vtkIntArray()
    label.SetName("label")
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        x = np.mean([points[ids.GetId(k), 0] for k in range(ids.GetNumberOfIds())])
        label.InsertNextValue(1 if x < 0 else 2)
    grid.GetCellData().AddArray(label)
    return grid


def grey_ramp_property():
    """Grey 0.2 at v = -0.5 to white at v = 0.5; extinction constant (opacity 0.6 per 0.5)."""
    ctf = vtkColorTransferFunction()
    ctf.AddRGBPoint(-0.5, 0.2, 0.2, 0.2)
    ctf.AddRGBPoint(0.5, 1, 1, 1)
    otf = vtkPiecewiseFunction()
    otf.AddPoint(-0.5, 0.6)
    otf.AddPoint(0.5, 0.6)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(0.5)
    return prop


W, H, SCALE = 120, 60, 0.6  # the view spans y in [-0.6, 0.6], x in [-1.2, 1.2]
mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(slab())
mapper.AutoAdjustSampleDistancesOff()
errors = messages(mapper)
prop = grey_ramp_property()
volume, ren, win = offscreen_scene(mapper, prop, W, H)
look_down_z(ren, SCALE)
assert mapper.GetLabelColoring() == adaptivert.vtkTetRayCastMapper.LABEL_COLORING_VALUES
assert mapper.GetLabelArrayName() == "label"


def colour_over_alpha():
    """Each pixel's colour / opacity (premultiplied image), its x and y, where the slab is seen
    well inside a label (not within a quarter of the interface or of the slab's ends)."""
    win.Render()
    last = mapper.GetLastImage()
    w, h = last.GetDimensions()[:2]
    img = vtk_to_numpy(last.GetPointData().GetScalars()).reshape(h, w, 4).astype(float)
    ys = -SCALE + (np.arange(h) + 0.5) * 2 * SCALE / h
    xs = -SCALE * w / h + (np.arange(w) + 0.5) * 2 * SCALE / h
    X, Y = np.meshgrid(xs, ys)
    keep = (np.abs(X) > 0.25) & (np.abs(X) < 0.9) & (np.abs(Y) < 0.45)
    alpha = img[..., 3]
    assert (alpha[keep] > 0.3).all(), f"the slab is not seen: opacity {alpha[keep].min():.3f}"
    return img[..., :3][keep] / alpha[keep][:, None], X[keep], Y[keep], alpha[keep]


def grey(y):
    return 0.2 + 0.8 * (y + 0.5)  # the ramp's luminance at y (equal channels: luminance = grey)


# Default: the values inside each label in its hue, brightness following the ramp exactly.
got, x, y, alpha = colour_over_alpha()
want = np.where((x < 0)[:, None], PALETTE[1], PALETTE[2]) * grey(y)[:, None]
err = np.abs(got - want).max()
print(f"values in each label: max |colour/alpha - hue x ramp| = {err:.2e}; opacity {alpha.min():.3f}..{alpha.max():.3f}")
assert err < 2e-3, err
# Opacity: 0.6 per 0.5 through 0.5 of slab.
assert np.allclose(alpha, 0.6, atol=2e-3), (alpha.min(), alpha.max())
# Brightness rises with y inside each label (the analytic check's point, said plainly).
for side, name in ((x < 0, "label 1"), (x > 0, "label 2")):
    order = np.argsort(y[side])
    bright = got[side].sum(1)[order]
    assert bright[-1] > 2.5 * bright[0], (name, bright[0], bright[-1])

# VTK's own per-label functions: label 2 red, brighter with v, opaque as the property says.
red = vtkColorTransferFunction()
red.AddRGBPoint(-0.5, 0.1, 0, 0)
red.AddRGBPoint(0.5, 0.9, 0, 0)
prop.SetLabelColor(2, red)
got, x, y, alpha = colour_over_alpha()
want2 = np.stack([0.1 + 0.8 * (y + 0.5), 0 * y, 0 * y], 1)
err2 = np.abs(got[x > 0] - want2[x > 0]).max()
err1 = np.abs(got[x < 0] - (np.array(PALETTE[1]) * grey(y)[:, None])[x < 0]).max()
print(f"SetLabelColor(2, red ramp): label 2 off by {err2:.2e}, label 1 (none set) off by {err1:.2e}")
assert err2 < 2e-3 and err1 < 2e-3, (err1, err2)
prop.SetLabelColor(2, None)

# Flat: each label in its colour, half opaque per unit distance.
mapper.SetLabelColoringToFlat()
got, x, y, alpha = colour_over_alpha()
want = np.where((x < 0)[:, None], PALETTE[1], PALETTE[2])
print(f"flat: max |colour/alpha - label colour| = {np.abs(got - want).max():.2e}")
assert np.abs(got - want).max() < 2e-3
assert np.allclose(alpha, 0.5, atol=2e-3), (alpha.min(), alpha.max())  # 0.5 per 0.5, through 0.5

# Off: the property's grey ramp over the values, labels ignored.
mapper.SetLabelColoringToOff()
got, x, y, alpha = colour_over_alpha()
print(f"off: max |colour/alpha - grey ramp| = {np.abs(got - grey(y)[:, None]).max():.2e}")
assert np.abs(got - grey(y)[:, None]).max() < 2e-3

assert not errors, errors
print("ok")
