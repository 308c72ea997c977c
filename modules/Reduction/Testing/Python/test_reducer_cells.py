"""vtkAdaptiveTetReducer on values stored on an image's cells (labels, finite-volume output).

Each cell is a voxel at its centre, as the file loader reads such images: a linear field sampled at
the cell centres must come back exact, on the box of the centres, both when the cells hold the only
values and when SetInputArrayToProcess picks a cell array beside point scalars. Before, the first
said 'the image has no point scalars' and the second 'the scalar array does not match the image
dimensions'.
"""
import adaptivert
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData


def linear(x, y, z):
    return 2 * x - y + 0.5 * z + 10


img = vtkImageData()
img.SetDimensions(9, 7, 5)  # 8 x 6 x 4 cells
img.SetSpacing(1.0, 2.0, 0.5)
img.SetOrigin(-4, 1, 2)
cells = vtkDoubleArray()
cells.SetName("pressure")
cells.SetNumberOfTuples(img.GetNumberOfCells())
for c in range(img.GetNumberOfCells()):
    box = img.GetCell(c).GetBounds()
    cells.SetTuple1(c, linear((box[0] + box[1]) / 2, (box[2] + box[3]) / 2, (box[4] + box[5]) / 2))
img.GetCellData().SetScalars(cells)


def check(r, label):
    r.SetTargetTets(24)
    r.SetSolverTolerance(1e-14)
    r.Update()
    out = r.GetOutput()
    assert out.GetNumberOfCells() > 0, label
    bounds = out.GetBounds()
    want = (-3.5, 3.5, 2.0, 12.0, 2.25, 3.75)  # the first and last cell centres
    print(f"{label}: {out.GetNumberOfCells()} tets, bounds {bounds}, RMS {r.GetRMSError():.2e}")
    assert all(abs(a - b) < 1e-9 for a, b in zip(bounds, want)), bounds
    values = out.GetPointData().GetArray("pressure")
    assert values is not None, [out.GetPointData().GetArrayName(i) for i in range(out.GetPointData().GetNumberOfArrays())]
    worst = max(abs(values.GetTuple1(i) - linear(*out.GetPoint(i))) for i in range(out.GetNumberOfPoints()))
    assert worst < 1e-8 and r.GetRMSError() < 1e-8, (worst, r.GetRMSError())


r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(img)
check(r, "cells only")

points = vtkFloatArray()
points.SetName("other")
points.SetNumberOfTuples(img.GetNumberOfPoints())
points.Fill(7.0)
img.GetPointData().SetScalars(points)
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(img)
r.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "pressure")
check(r, "cell array chosen beside point scalars")

# Point arrays none of which is active, beside a cell array (numpy_support + AddArray, many .vti
# files): the first one-component point array is reduced, as `reduce` takes it; the cell array
# was reduced instead, and point arrays alone were 'the image has no point scalars'.
img.GetPointData().SetActiveScalars(None)
ids = vtkFloatArray()
ids.SetName("cell_id")
ids.SetNumberOfTuples(img.GetNumberOfCells())
for c in range(img.GetNumberOfCells()):
    ids.SetTuple1(c, c)
img.GetCellData().SetScalars(ids)
for with_cells in (True, False):
    if not with_cells:
        img.GetCellData().Initialize()
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(img)
    r.SetTargetTets(24)
    r.Update()
    got = r.GetOutput().GetPointData().GetScalars()
    print(f"inactive point arrays, cell array {with_cells}: reduced {got.GetName() if got else None}")
    assert got is not None and got.GetName() == "other", with_cells

# A misspelt cell array is named as a cell array, with the cell arrays listed (it said 'no point
# array' and listed the point arrays).
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
img.GetCellData().AddArray(cells)
messages = []


@calldata_type(VTK_STRING)
def on_error(caller, event, text):
    messages.append(text)


r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(img)
r.SetTargetTets(24)
r.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_CELLS, "presure")
r.AddObserver(vtkCommand.ErrorEvent, on_error)
r.Update()
print(messages)
assert len(messages) == 1 and "no cell array 'presure' (cell arrays: pressure)" in messages[0], messages
print("ok")
