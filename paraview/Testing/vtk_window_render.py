"""Renders a tet mesh with vtkTetRayCastMapper in a plain VTK window of the project's own VTK
(Debian's VTK 9.1, run by /usr/bin/python3), for the ParaView tests to compare against:
    vtk_window_render.py MESH.vtu TF_FILE OUT.png W H  PX PY PZ  FX FY FZ  UX UY UZ  ANGLE [OPTIONS]
with `adaptivert render`'s --integrator exact|trapezoid, --iso V, --iso-opacity A and --ert E."""
import sys

import adaptivert
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (draws the mapper's image)

mesh, tf, out = sys.argv[1:4]
w, h = int(sys.argv[4]), int(sys.argv[5])
position, focal, up = ([float(v) for v in sys.argv[i:i + 3]] for i in (6, 9, 12))
angle = float(sys.argv[15])
options = dict(zip(sys.argv[16::2], sys.argv[17::2]))

reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(mesh)
colour, opacity, unit = vtkColorTransferFunction(), vtkPiecewiseFunction(), 1.0
for line in open(tf):
    words = line.split("#")[0].split()
    if words and words[0] == "unit-distance":
        unit = float(words[1])
    elif words:
        s, r, g, b, a = (float(x) for x in words)
        colour.AddRGBPoint(s, r, g, b)
        opacity.AddPoint(s, a)
prop = vtkVolumeProperty()
prop.SetColor(colour)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(unit)
mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputConnection(reader.GetOutputPort())
mapper.SetAutoAdjustSampleDistances(0)
mapper.SetTrapezoidRule(options.get("--integrator") == "trapezoid")
mapper.SetEarlyRayTermination(float(options.get("--ert", 0.99)))
if "--iso" in options:  # render's first iso colour
    mapper.AddIsoSurface(float(options["--iso"]), 1, 0.85, 0.7, float(options.get("--iso-opacity", 1)))
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
ren = vtkRenderer()
ren.AddVolume(volume)
ren.SetBackground(0, 0, 0)
win = vtkRenderWindow()
win.SetOffScreenRendering(1)
win.SetSize(w, h)
win.AddRenderer(ren)
cam = ren.GetActiveCamera()
cam.SetPosition(*position)
cam.SetFocalPoint(*focal)
cam.SetViewUp(*up)
cam.SetViewAngle(angle)
ren.ResetCameraClippingRange()
win.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(win)
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(out)
writer.Write()
