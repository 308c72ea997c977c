"""vtkAdaptiveTetReducer from Python: a real pipeline, analytic answers, levels, errors, progress."""
import math

import adaptivert
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray, vtkFloatArray, vtkShortArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkMultiBlockDataSet, vtkUnstructuredGrid


def image(dims, fn, array=vtkFloatArray, name="density", spacing=(1, 1, 1), origin=(0, 0, 0)):
    img = vtkImageData()
    img.SetDimensions(*dims)
    img.SetSpacing(*spacing)
    img.SetOrigin(*origin)
    a = array()
    a.SetName(name)
    a.SetNumberOfTuples(img.GetNumberOfPoints())
    for i in range(img.GetNumberOfPoints()):
        a.SetTuple1(i, fn(*img.GetPoint(i)))
    img.GetPointData().SetScalars(a)
    return img


# A linear ramp in double precision is reproduced by the coarse mesh.
ramp = image((17, 13, 9), lambda x, y, z: 3 * x - y + 0.25 * z, vtkDoubleArray, "ramp",
             spacing=(0.5, 1.0, 2.0), origin=(1, -2, 3))
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(ramp)
r.SetTargetTets(24)
r.SetSolverTolerance(1e-14)
r.Update()
g = r.GetOutput()
assert isinstance(g, vtkUnstructuredGrid)
assert g.GetNumberOfCells() <= 24 and g.GetNumberOfCells() >= 6
assert all(g.GetCellType(i) == 10 for i in range(g.GetNumberOfCells()))  # VTK_TETRA
assert g.GetPointData().GetScalars().GetName() == "ramp"
assert g.GetPointData().GetScalars().GetDataTypeAsString() == "double"
assert r.GetRMSError() < 1e-9, r.GetRMSError()
assert g.GetBounds() == ramp.GetBounds(), (g.GetBounds(), ramp.GetBounds())
# The input's mean voxel spacing travels with the mesh: a preset's unit distance follows it.
assert abs(g.GetFieldData().GetArray("source_spacing").GetValue(0) - 1.0) < 1e-12  # (0.5 * 1 * 2)^(1/3)

# SetInputArrayToProcess picks another point array: a second, curved array is reduced instead
# (its name on the output, and no longer reproduced exactly by 24 tets).
curved = vtkDoubleArray()
curved.SetName("curved")
curved.SetNumberOfTuples(ramp.GetNumberOfPoints())
for i in range(ramp.GetNumberOfPoints()):
    x, y, z = ramp.GetPoint(i)
    curved.SetTuple1(i, x * x + y * z)
ramp.GetPointData().AddArray(curved)
r.SetInputArrayToProcess(0, 0, 0, 0, "curved")  # 0: vtkDataObject.FIELD_ASSOCIATION_POINTS
r.Update()
assert r.GetOutput().GetPointData().GetScalars().GetName() == "curved"
assert r.GetRMSError() > 1e-3, r.GetRMSError()

# A quadratic field over nested levels from one run; progress events fire.
quad = image((30, 26, 22), lambda x, y, z: (x - 12) ** 2 + 0.5 * (y - 10) ** 2 + 2 * (z - 7) ** 2,
             vtkShortArray, "quad")
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(quad)
r.SetTargetTets(4000)
for n in (100, 400, 1500):
    r.AddLevel(n)
assert r.GetNumberOfLevels() == 3
seen = []
r.AddObserver(vtkCommand.ProgressEvent, lambda o, e: seen.append(o.GetProgress()))
r.Update()
assert seen and seen[-1] == 1.0, seen[-3:]
g = r.GetOutput()
assert abs(g.GetNumberOfCells() - 4000) <= 200, g.GetNumberOfCells()
fd = g.GetFieldData()
for name in ("rms_error", "max_error", "tets", "vertices", "build_seconds", "target_tets", "target_error"):
    assert fd.GetArray(name) is not None, name
assert fd.GetArray("tets").GetValue(0) == g.GetNumberOfCells()
assert fd.GetArray("vertices").GetValue(0) == g.GetNumberOfPoints()
assert abs(fd.GetArray("rms_error").GetValue(0) - r.GetRMSError()) < 1e-12
assert g.GetCellData().GetArray("approximation_error").GetNumberOfTuples() == g.GetNumberOfCells()
assert g.GetPointData().GetScalars().GetDataTypeAsString() == "float"
levels = r.GetOutputDataObject(1)
assert isinstance(levels, vtkMultiBlockDataSet) and levels.GetNumberOfBlocks() == 4
errors = [levels.GetBlock(i).GetFieldData().GetArray("rms_error").GetValue(0) for i in range(4)]
counts = [levels.GetBlock(i).GetNumberOfCells() for i in range(4)]
assert all(a > b for a, b in zip(errors, errors[1:])), errors
assert all(abs(c - n) <= 0.05 * n for c, n in zip(counts, (100, 400, 1500, 4000))), counts

# Error-driven edge splits instead of newest-vertex bisection: same budget, a valid mesh, a
# lower error on this field than bisection's at the same count.
e = adaptivert.vtkAdaptiveTetReducer()
e.SetInputData(quad)
e.SetTargetTets(1500)
assert e.GetRefinement() == e.BISECTION
e.SetRefinementToEdgeSplit()
assert e.GetRefinement() == e.EDGE_SPLIT
e.Update()
assert abs(e.GetOutput().GetNumberOfCells() - 1500) <= 75, e.GetOutput().GetNumberOfCells()
assert e.GetRMSError() < errors[2], (e.GetRMSError(), errors[2])

# An error target as a fraction of the range, on the max error.
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(quad)
r.SetTargetError(0.02)
r.ErrorRelativeOn()
r.SetErrorMetricToMax()
r.Update()
rng = quad.GetPointData().GetScalars().GetRange()
assert r.GetMaxError() <= 0.02 * (rng[1] - rng[0]), (r.GetMaxError(), rng)

# A 2-D image is refused with one clear error, not a crash; the output stays empty.
messages = []
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(image((8, 8, 1), lambda x, y, z: x))
r.SetTargetTets(100)
r.AddObserver(vtkCommand.ErrorEvent, lambda o, e: messages.append(e))
r.Update()
assert messages, "no error reported for a 2-D image"
assert r.GetOutput().GetNumberOfCells() == 0
# Reduce for a transfer function (the tet counts are checked in TestOpacityImportance): the API,
# the figures and the field data. Equal ripples either side of a step; the left half's values
# have no opacity, so the weighted run fits them worse and its weighted error is below its plain.
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
ripples = image((40, 24, 24), lambda x, y, z: (0.2 if x < 20 else 0.8) + 0.15 * math.sin(0.5 * y) * math.sin(0.4 * z))
opacity = vtkPiecewiseFunction()
opacity.AddPoint(0.0, 0.0)
opacity.AddPoint(0.5, 0.0)
opacity.AddPoint(1.0, 1.0)


def left_cells(grid):
    n = 0
    for i in range(grid.GetNumberOfCells()):
        b = grid.GetCell(i).GetBounds()
        n += (b[0] + b[1]) / 2 < 16
    return n


runs = {}
for weighted in (False, True):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(ripples)
    r.SetTargetTets(1500)
    if weighted:
        r.SetScalarOpacity(opacity)
        r.SetImportanceRadius(1)
        assert r.GetScalarOpacity() is opacity and r.GetImportanceRadius() == 1
    r.Update()
    fd = r.GetOutput().GetFieldData()
    assert fd.GetArray("weighted").GetValue(0) == (1 if weighted else 0)
    assert abs(fd.GetArray("weighted_rms_error").GetValue(0) - r.GetWeightedRMSError()) < 1e-12
    runs[weighted] = (left_cells(r.GetOutput()), r.GetRMSError(), r.GetWeightedRMSError())
assert runs[True][0] <= runs[False][0], runs
assert runs[True][2] < 0.5 * runs[True][1], runs
assert runs[True][1] > runs[False][1], runs  # the plain error pays for what is not seen

# Iso-values reach the weighting (their effect is TestOpacityImportance's): the reduction changes
# with one, re-executes after AddIsoValue, and is the same again once they are removed.
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(ripples)
r.SetTargetTets(1500)
r.SetScalarOpacity(opacity)
r.SetImportanceRadius(1)
r.Update()
plainIso = (left_cells(r.GetOutput()), r.GetWeightedRMSError())
assert plainIso == runs[True][::2], (plainIso, runs)
r.AddIsoValue(0.2)
assert r.GetNumberOfIsoValues() == 1 and r.GetIsoValue(0) == 0.2
r.Update()
withIso = (left_cells(r.GetOutput()), r.GetWeightedRMSError())
assert withIso != plainIso, withIso
r.RemoveAllIsoValues()
r.Update()
assert (left_cells(r.GetOutput()), r.GetWeightedRMSError()) == plainIso

# ClampToVoxels keeps every output value inside the input's range (the plain fit overshoots it).
lo, hi = ripples.GetPointData().GetScalars().GetRange()
ranges = {}
for clamp in (False, True):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(ripples)
    r.SetTargetTets(1500)
    r.SetClampToVoxels(clamp)
    r.Update()
    ranges[clamp] = r.GetOutput().GetPointData().GetScalars().GetRange()
assert ranges[False][0] < lo - 1e-6 or ranges[False][1] > hi + 1e-6, (ranges, lo, hi)
assert ranges[True][0] >= lo and ranges[True][1] <= hi, (ranges, lo, hi)

# CapOpacity (on by default with a ScalarOpacity): no value more opaque than the voxels under it,
# so with an opacity rising past the top of the range nothing is fitted above it.
rising = vtkPiecewiseFunction()
rising.AddPoint(lo, 0.0)
rising.AddPoint(2 * hi, 1.0)
tops = {}
for cap in (False, True):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(ripples)
    r.SetTargetTets(1500)
    r.SetScalarOpacity(rising)
    if not cap:
        r.CapOpacityOff()
    assert r.GetCapOpacity() == cap
    r.Update()
    tops[cap] = r.GetOutput().GetPointData().GetScalars().GetRange()
assert tops[False][1] > hi + 1e-6 and tops[True][1] <= hi, (tops, lo, hi)
assert tops[True][0] == tops[False][0], tops  # the clearer side keeps its overshoot

# A named array that is not there is an error listing the arrays, not a reduction of the scalars.
messages = []
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(ripples)
r.SetTargetTets(100)
r.SetInputArrayToProcess(0, 0, 0, 0, "nope")  # point data
r.AddObserver(vtkCommand.ErrorEvent, lambda o, e: messages.append(e))
r.Update()
assert r.GetOutput().GetNumberOfCells() == 0, r.GetOutput().GetNumberOfCells()
assert messages, "no error for a missing array"

# An empty opacity function is a clear error.
messages = []
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(ripples)
r.SetTargetTets(100)
r.SetScalarOpacity(vtkPiecewiseFunction())
r.AddObserver(vtkCommand.ErrorEvent, lambda o, e: messages.append(e))
r.Update()
assert messages and r.GetOutput().GetNumberOfCells() == 0

print("ok", errors, counts, runs)

# Vertex relocation: a step off the coarse grid is fitted far better at the same tet count.
step = image((25, 11, 11), lambda x, y, z: 1000.0 if x > 7.5 else 0.0)
reloc = []
for relocate in (False, True):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(step)
    r.SetTargetTets(300)
    r.SetRelocateVertices(relocate)
    assert r.GetRelocateVertices() == relocate
    shown = []
    r.AddObserver(vtkCommand.ProgressEvent, lambda o, e: shown.append(o.GetProgress()))
    r.Update()
    # The relocation reports too (the second half of the bar), and the progress only rises.
    assert shown == sorted(shown) and shown[-1] == 1.0, shown
    assert not relocate or len([f for f in shown if 0.5 < f < 1.0]) >= 2, shown
    assert r.GetOutput().GetBounds() == step.GetBounds()
    reloc.append((r.GetOutput().GetNumberOfCells(), r.GetRMSError()))
assert reloc[1][0] == reloc[0][0], reloc
assert reloc[1][1] < 0.8 * reloc[0][1], reloc

# 32- and 64-bit integers are reduced in double precision and come back as double, as `reduce`
# writes them: a ramp at 1e8 (exact for the coarse mesh) was stored as float, 3 units off while the
# field data said RMS 1e-8.
from vtkmodules.vtkCommonCore import vtkTypeInt32Array, vtkTypeInt64Array, vtkUnsignedCharArray


def big_ramp(x, y, z):
    return 100000000 + x + 2 * y + 3 * z


for array, kind in ((vtkTypeInt32Array, "double"), (vtkTypeInt64Array, "double"), (vtkUnsignedCharArray, "float")):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(image((12, 10, 9), big_ramp if kind == "double" else (lambda x, y, z: x + 2 * y), array))
    r.SetTargetTets(6)
    r.SetSolverTolerance(1e-15)
    r.Update()
    g = r.GetOutput()
    s = g.GetPointData().GetScalars()
    assert s.GetDataTypeAsString() == kind, (array.__name__, s.GetDataTypeAsString())
    if kind == "double":
        worst = max(abs(s.GetTuple1(i) - big_ramp(*g.GetPoint(i))) for i in range(g.GetNumberOfPoints()))
        assert worst < 1e-4, (array.__name__, worst)

# The input's field data passes through beside the reduction's figures (VTK's dataset filters pass
# it; it was dropped), and a level the final grid already is, or one an error target stops short
# of, is named in a warning instead of leaving port 1 a block short without a word.
from vtkmodules.vtkCommonCore import vtkStringArray
tagged = image((12, 10, 9), lambda x, y, z: x * x + y - z)
note = vtkStringArray()
note.SetName("PatientName")
note.InsertNextValue("Anonymous")
tagged.GetFieldData().AddArray(note)
warnings = []
r = adaptivert.vtkAdaptiveTetReducer()
r.SetInputData(tagged)
r.SetTargetTets(300)
r.AddLevel(100)
r.AddLevel(300)
r.AddObserver(vtkCommand.WarningEvent, lambda o, e: warnings.append(e))
r.Update()
fd = r.GetOutput().GetFieldData()
assert fd.GetAbstractArray("PatientName") and fd.GetAbstractArray("PatientName").GetValue(0) == "Anonymous"
assert fd.GetArray("rms_error") is not None, [fd.GetArrayName(i) for i in range(fd.GetNumberOfArrays())]
levels = r.GetOutputDataObject(1)
assert levels.GetNumberOfBlocks() == 2, levels.GetNumberOfBlocks()
assert levels.GetBlock(0).GetFieldData().GetAbstractArray("PatientName") is not None
assert len(warnings) == 1, warnings
warnings.clear()
r.RemoveAllLevels()
r.SetTargetTets(0)
r.SetTargetError(0.5)
r.ErrorRelativeOn()
r.AddLevel(50000)
r.Update()
assert len(warnings) == 1 and r.GetOutputDataObject(1).GetNumberOfBlocks() == 1, (warnings, r.GetOutputDataObject(1).GetNumberOfBlocks())
