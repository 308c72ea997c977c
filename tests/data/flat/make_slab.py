"""Writes slab-z.vti: a 24 x 24 x 2 float volume (a slab two voxels thick in z, as a single-layer
simulation or a two-slice scan gives), a disc of 'density' 1 at the centre falling to 0 at radius
11. Run with /usr/bin/python3 (VTK's Python)."""
import math

from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

image = vtkImageData()
image.SetDimensions(24, 24, 2)
density = vtkFloatArray()
density.SetName("density")
for k in range(2):
    for j in range(24):
        for i in range(24):
            density.InsertNextValue(max(0.0, 1.0 - math.hypot(i - 11.5, j - 11.5) / 11.0))
image.GetPointData().SetScalars(density)
writer = vtkXMLImageDataWriter()
writer.SetFileName("slab-z.vti")
writer.SetInputData(image)
writer.SetDataModeToAscii()
writer.Write()
