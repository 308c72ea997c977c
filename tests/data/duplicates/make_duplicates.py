"""Writes box-shared.vtu and box-own-points.vtu: a 1 x 1 x 1 box of 5 x 5 x 5 points (320 tets, a
field 'f' that is not CT-like, 0.3 .. 0.65), once with the tets sharing their points and once with
every tet keeping its own four (vtkShrinkFilter at factor 1, as some exporters write meshes). A
preset's unit distance follows the mesh's sample spacing, so both must render alike. Run with
/usr/bin/python3 in this folder."""
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter, vtkShrinkFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

img = vtkImageData()
img.SetDimensions(5, 5, 5)
img.SetSpacing(0.25, 0.25, 0.25)
img.AllocateScalars(10, 1)  # VTK_FLOAT
f = img.GetPointData().GetScalars()
f.SetName("f")
for i in range(img.GetNumberOfPoints()):
    x, y, z = img.GetPoint(i)
    f.SetValue(i, 0.3 + 0.2 * x - 0.1 * y + 0.25 * z + 0.1 * x * y)
tets = vtkDataSetTriangleFilter()
tets.SetInputData(img)
own = vtkShrinkFilter()
own.SetShrinkFactor(1.0)
own.SetInputConnection(tets.GetOutputPort())
for name, port in (("box-shared.vtu", tets.GetOutputPort()), ("box-own-points.vtu", own.GetOutputPort())):
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputConnection(port)
    writer.SetFileName(name)
    writer.Write()
