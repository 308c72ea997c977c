#!/usr/bin/python3
"""A VTK pipeline with AdaptiveRT: read a CT volume (any format adaptivert reads, through
adaptivert.vtkAdaptiveRTReader: .mha .nii.gz .nrrd .vti, DICOM folders, ...), reduce it to an adaptive tetrahedral mesh
with vtkAdaptiveTetReducer (for the transfer function it will be shown with), and volume-render the mesh with vtkTetRayCastMapper in an ordinary
vtkRenderWindow; then save a screenshot.

    /usr/bin/python3 reduce_and_render.py [VOLUME] [OUT.png] [TETS]

Needs a display (run under `xvfb-run -a` on a machine without one).
"""
import os
import sys

import adaptivert
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401  (draws the mapper's image)

if not os.environ.get("DISPLAY"):
    print("skipped: no X display (VTK draws only through X here; use xvfb-run -a)")
    sys.exit(77)

here = os.path.dirname(os.path.abspath(__file__))
volume_file = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "ct-head-128.mha")
out_file = sys.argv[2] if len(sys.argv) > 2 else "reduce_and_render.png"
tets = int(sys.argv[3]) if len(sys.argv) > 3 else 30000

# The reader adaptivert itself uses: the same placement (LPS patient coordinates; SetFrame("vtk")
# for VTK's and ParaView's), the same checks, and one line saying what is wrong with a bad file.
reader = adaptivert.vtkAdaptiveRTReader()
reader.SetFileName(volume_file)
reader.Update()
if reader.GetErrorMessage():
    sys.exit("reduce_and_render.py: " + reader.GetErrorMessage())

# A CT transfer function: soft tissue faint, bone opaque (HU).
colour = vtkColorTransferFunction()
colour.AddRGBPoint(-1024, 0.0, 0.0, 0.0)
colour.AddRGBPoint(-300, 0.75, 0.45, 0.35)
colour.AddRGBPoint(300, 1.0, 0.9, 0.8)
colour.AddRGBPoint(2000, 1.0, 1.0, 1.0)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(-1024, 0.0)
opacity.AddPoint(-400, 0.0)
opacity.AddPoint(-100, 0.02)
opacity.AddPoint(200, 0.05)
opacity.AddPoint(600, 0.6)
opacity.AddPoint(2000, 0.9)
prop = vtkVolumeProperty()
prop.SetColor(colour)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(2.0)

reducer = adaptivert.vtkAdaptiveTetReducer()
reducer.SetInputConnection(reader.GetOutputPort())
reducer.SetTargetTets(tets)
# Reduce for what the transfer function shows (tets where opacity changes), then move the
# vertices onto the surfaces they fit: what `adaptivert render` does, 2-6 dB closer to the voxels
# than a plain fit at the same tets.
reducer.SetScalarOpacity(opacity)
reducer.RelocateVerticesOn()
reducer.Update()
mesh = reducer.GetOutput()
print(f"reduced to {mesh.GetNumberOfCells()} tets, {mesh.GetNumberOfPoints()} vertices, "
      f"RMS error {reducer.GetRMSError():.1f} HU (opacity-weighted {reducer.GetWeightedRMSError():.1f}), "
      f"{reducer.GetBuildSeconds():.2f} s")

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(mesh)
mapper.SetEarlyRayTermination(0.99)
actor = vtkVolume()
actor.SetMapper(mapper)
actor.SetProperty(prop)

ren = vtkRenderer()
ren.AddVolume(actor)
ren.SetBackground(0, 0, 0)
cam = ren.GetActiveCamera()
cam.SetPosition(0, -1, 0)
cam.SetFocalPoint(0, 0, 0)
cam.SetViewUp(0, 0, 1)
ren.ResetCamera()
cam.Zoom(1.3)
win = vtkRenderWindow()
win.SetSize(320, 320)
win.AddRenderer(ren)
win.Render()
print(f"rendered in {mapper.GetLastRenderTime():.3f} s, {mapper.GetLastTetsCrossed():.0f} tets crossed")

grab = vtkWindowToImageFilter()
grab.SetInput(win)
grab.Update()
writer = vtkPNGWriter()
writer.SetFileName(out_file)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", out_file)

# The head covers a good part of the picture, and the mapper really walked the mesh.
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float) / 255.0
lit = (rgb[:, :3].max(axis=1) > 0.1).mean()
print(f"{100 * lit:.1f}% of the pixels show the head")
assert 0.15 < lit < 0.9, lit
assert mapper.GetLastTetsCrossed() > mesh.GetNumberOfCells(), "rays should cross many tets"
assert abs(mesh.GetNumberOfCells() - tets) <= 0.05 * tets, "the reducer meets its budget within 5%"
