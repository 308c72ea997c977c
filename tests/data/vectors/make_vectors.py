"""Writes velocity-box.vtu: a 4 x 4 x 4 box of tets with a point vector 'velocity' (its magnitude
grows away from the centre, its x component along x) and a cell array 'region' (0 or 1 by the
cell's side of x = 1.5), for the viewer's --array tests. Run with /usr/bin/python3."""
import math

from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

img = vtkImageData()
img.SetDimensions(4, 4, 4)
v = vtkFloatArray()
v.SetName("velocity")
v.SetNumberOfComponents(3)
v.SetNumberOfTuples(img.GetNumberOfPoints())
for i in range(img.GetNumberOfPoints()):
    x, y, z = img.GetPoint(i)
    v.SetTuple3(i, x, y - 1.5, z - 1.5)
img.GetPointData().AddArray(v)
tets = vtkDataSetTriangleFilter()
tets.SetInputData(img)
tets.Update()
grid = tets.GetOutput()
region = vtkFloatArray()
region.SetName("region")
region.SetNumberOfTuples(grid.GetNumberOfCells())
for c in range(grid.GetNumberOfCells()):
    b = grid.GetCell(c).GetBounds()
    region.SetValue(c, 1.0 if (b[0] + b[1]) / 2 > 1.5 else 0.0)
grid.GetCellData().AddArray(region)
w = vtkXMLUnstructuredGridWriter()
w.SetInputData(grid)
w.SetDataModeToAscii()
w.SetFileName("velocity-box.vtu")
w.Write()
