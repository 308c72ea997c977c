"""Writes half-box.vtu: a 2 x 2 x 2 box of 5 x 5 x 5 points (320 tets, a linear field 'f') clipped
at x = 0 by vtkTableBasedClipDataSet (ParaView's Clip with its default plane through the centre).
The plane goes through grid points, so the clip leaves flat pieces on it beside the 160 tets of
the kept half. Run with /usr/bin/python3."""
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPlane
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter, vtkTableBasedClipDataSet
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

img = vtkImageData()
img.SetDimensions(5, 5, 5)
img.SetOrigin(-1, -1, -1)
img.SetSpacing(0.5, 0.5, 0.5)
img.AllocateScalars(10, 1)  # VTK_FLOAT
f = img.GetPointData().GetScalars()
f.SetName("f")
for i in range(img.GetNumberOfPoints()):
    x, y, z = img.GetPoint(i)
    f.SetValue(i, 1 + x + 0.5 * y + 0.25 * z)
tets = vtkDataSetTriangleFilter()
tets.SetInputData(img)
plane = vtkPlane()
plane.SetOrigin(0, 0, 0)
plane.SetNormal(1, 0, 0)
clip = vtkTableBasedClipDataSet()
clip.SetInputConnection(tets.GetOutputPort())
clip.SetClipFunction(plane)
writer = vtkXMLUnstructuredGridWriter()
writer.SetInputConnection(clip.GetOutputPort())
writer.SetFileName("half-box.vtu")
writer.Write()
