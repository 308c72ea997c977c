"""vtkTetRayCastMapper shades the volume when the property says ShadeOn.

A linear field has one gradient, and a parallel camera looking down z sees it at one angle, so
the mapper's float image (GetLastImage) lit is (ambient + diffuse |n.v|) times the unlit one plus
specular |n.v|^power times its opacity, pixel by pixel, with the property's own coefficients; the
opacity does not change. Needs a display (skips with exit 77).
"""
import math

from mapper_scene import look_down_z, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty

import adaptivert

gradient = (0.2, 0.1, 0.3)
image = vtkImageData()
image.SetDimensions(6, 6, 6)
image.SetOrigin(-1, -1, -1)
image.SetSpacing(0.4, 0.4, 0.4)
pts = np.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
field = numpy_to_vtk(1.0 + pts @ np.array(gradient), deep=1)
field.SetName("f")
image.GetPointData().SetScalars(field)
tri = vtkDataSetTriangleFilter()
tri.SetInputData(image)
tri.Update()

ctf = vtkColorTransferFunction()
ctf.AddRGBPoint(0.0, 0.1, 0.8, 0.3)
ctf.AddRGBPoint(2.0, 0.9, 0.2, 0.6)
otf = vtkPiecewiseFunction()
otf.AddPoint(0.0, 0.2)
otf.AddPoint(2.0, 0.5)
prop = vtkVolumeProperty()
prop.SetColor(ctf)
prop.SetScalarOpacity(otf)
prop.SetAmbient(0.25)
prop.SetDiffuse(0.5)
prop.SetSpecular(0.3)
prop.SetSpecularPower(6)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(tri.GetOutput())
mapper.SetAutoAdjustSampleDistances(0)
volume, ren, win = offscreen_scene(mapper, prop, 48, 40)
look_down_z(ren, 1.3)


def last_image():
    win.Render()
    img = mapper.GetLastImage()
    w, h = img.GetDimensions()[:2]
    return vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, 4).copy()


plain = last_image()
prop.ShadeOn()
lit = last_image()
nv = abs(gradient[2]) / math.sqrt(sum(c * c for c in gradient))
a = 0.25 + 0.5 * nv
spec = 0.3 * nv ** 6
expected = a * plain[..., :3] + spec * plain[..., 3:4]
worst = float(np.abs(lit[..., :3] - expected).max())
changed = float(np.abs(lit[..., :3] - plain[..., :3]).max())
print("covered", float((plain[..., 3] > 0).mean()), "worst", worst, "changed", changed)
assert (plain[..., 3] > 0).mean() > 0.3, "the box covers the image's middle"
assert np.array_equal(lit[..., 3], plain[..., 3]), "shading changes colour, not opacity"
assert worst <= 2e-6, worst
assert changed > 0.05, changed
prop.ShadeOff()
assert np.array_equal(last_image(), plain), "ShadeOff draws the unlit image again"
print("ok")
