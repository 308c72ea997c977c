"""Writes hex-and-triangle.vtu: one unit hexahedron with a linear point scalar 'f' and one
triangle on its bottom face, as ParaView's output often mixes surface cells into a volume mesh.
Run with /usr/bin/python3 (VTK's Python)."""
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_TRIANGLE, vtkUnstructuredGrid
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

points = vtkPoints()
f = vtkDoubleArray()
f.SetName("f")
for x, y, z in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]:
    points.InsertNextPoint(x, y, z)
    f.InsertNextValue(x + 2 * y + 3 * z)
grid = vtkUnstructuredGrid()
grid.SetPoints(points)
grid.GetPointData().SetScalars(f)
grid.InsertNextCell(VTK_HEXAHEDRON, 8, list(range(8)))
grid.InsertNextCell(VTK_TRIANGLE, 3, [0, 1, 2])
writer = vtkXMLUnstructuredGridWriter()
writer.SetFileName("hex-and-triangle.vtu")
writer.SetInputData(grid)
writer.SetDataModeToAscii()
writer.Write()
