"""The meshing filters from Python: vtkSurfaceTetrahedralizer meshes a closed sphere surface to
its enclosed volume with progress events, and refuses an open one with an error event naming the
open edges; vtkAdaptiveTetReducer.SetRegion meshes a sphere of 1 in a box of 0 through CGAL's
mesher (the object-factory override registered by importing the package), and SetLabels with
SetValuesConnection fits a second volume's values inside the sphere as a label."""
import math

import adaptivert
from vtkmodules.vtkCommonCore import vtkCommand, vtkFloatArray, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkMassProperties
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkImagingCore import vtkImageShiftScale

sphere = vtkSphereSource()
sphere.SetRadius(2.0)
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(12)
clean = vtkCleanPolyData()
clean.SetInputConnection(sphere.GetOutputPort())
clean.Update()
mass = vtkMassProperties()
mass.SetInputConnection(clean.GetOutputPort())
mass.Update()

tet = adaptivert.vtkSurfaceTetrahedralizer()
tet.SetInputConnection(clean.GetOutputPort())
tet.SetTargetTets(3000)
progress = []
tet.AddObserver(vtkCommand.ProgressEvent, lambda c, e: progress.append(c.GetProgress()))
tet.Update()
grid = tet.GetOutput()
print(f"{grid.GetNumberOfCells()} tets, mesh volume {tet.GetMeshVolume():.6f}, surface {mass.GetVolume():.6f}")
assert grid.GetNumberOfCells() > 1500, grid.GetNumberOfCells()
assert abs(tet.GetMeshVolume() - mass.GetVolume()) < 1e-5 * mass.GetVolume()
assert abs(tet.GetSurfaceVolume() - mass.GetVolume()) < 1e-5 * mass.GetVolume()
assert progress and max(progress) == 1.0, progress

# The mesh's own boundary is the surface: its area is the sphere polyhedron's.
surf = vtkDataSetSurfaceFilter()
surf.SetInputData(grid)
surf.Update()
boundary = vtkMassProperties()
boundary.SetInputData(surf.GetOutput())
boundary.Update()
assert abs(boundary.GetSurfaceArea() - mass.GetSurfaceArea()) < 1e-4 * mass.GetSurfaceArea()

opened = clean.GetOutput().NewInstance()
opened.DeepCopy(clean.GetOutput())
opened.DeleteCell(0)
opened.RemoveDeletedCells()
errors = []
bad = adaptivert.vtkSurfaceTetrahedralizer()
bad.SetInputData(opened)
bad.SetTargetTets(100)
bad.AddObserver(vtkCommand.ErrorEvent, lambda c, e: errors.append(e))
bad.Update()
assert bad.GetOutput().GetNumberOfCells() == 0
assert errors, "no error event for an open surface"

n, c, R = 28, 13.5, 9.0
image = vtkImageData()
image.SetDimensions(n, n, n)
values = vtkUnsignedCharArray()
values.SetName("v")
values.SetNumberOfTuples(n * n * n)
for k in range(n):
    for j in range(n):
        for i in range(n):
            values.SetValue(i + n * (j + n * k), 1 if (i - c) ** 2 + (j - c) ** 2 + (k - c) ** 2 <= R * R else 0)
image.GetPointData().SetScalars(values)
reducer = adaptivert.vtkAdaptiveTetReducer()
reducer.SetInputData(image)
reducer.SetRegion(0.5, 1.0)
reducer.SetTargetTets(2000)
reducer.Update()
out = reducer.GetOutput()
s2 = vtkDataSetSurfaceFilter()
s2.SetInputData(out)
s2.Update()
m2 = vtkMassProperties()
m2.SetInputData(s2.GetOutput())
m2.Update()
expected = 4 / 3 * math.pi * R ** 3
print(f"region: {out.GetNumberOfCells()} tets, volume {m2.GetVolume():.1f} (sphere {expected:.1f}), "
      f"{reducer.GetRegionVoxels()} voxels")
assert out.GetNumberOfCells() > 500
assert abs(m2.GetVolume() - expected) < 0.03 * expected
assert out.GetFieldData().GetArray("region_voxels").GetValue(0) == reducer.GetRegionVoxels()

# A label map with a second volume's values on input port 1, from a pipeline
# (SetValuesConnection), as `reduce --labels --values` fits them: the sphere as label 1 and the
# values 3 x + 100 (vtkImageShiftScale of an x ramp) fitted inside it, within half a voxel's step
# (1.5) at every mesh point.
ramp = vtkImageData()
ramp.SetDimensions(n, n, n)
xs = vtkFloatArray()
xs.SetName("x")
xs.SetNumberOfTuples(n * n * n)
for p in range(n * n * n):
    xs.SetValue(p, float(p % n))
ramp.GetPointData().SetScalars(xs)
shift = vtkImageShiftScale()
shift.SetInputData(ramp)
shift.SetScale(3.0)
shift.SetShift(100.0 / 3.0)  # (x + shift) * scale
shift.SetOutputScalarTypeToFloat()
labels = adaptivert.vtkAdaptiveTetReducer()
labels.SetInputData(image)
labels.SetValuesConnection(shift.GetOutputPort())
labels.SetLabels(True)
labels.SetTargetTets(2000)
labels.Update()
out = labels.GetOutput()
v = out.GetPointData().GetScalars()
assert v is not None and out.GetCellData().GetArray("label") is not None
worst = max(abs(v.GetTuple1(p) - (3.0 * out.GetPoint(p)[0] + 100.0)) for p in range(out.GetNumberOfPoints()))
print(f"labels with values: {out.GetNumberOfCells()} tets, RMS {labels.GetRMSError():.3g}, worst point {worst:.3f}")
assert out.GetNumberOfCells() > 500
assert worst < 1.5, worst
assert labels.GetRMSError() < 0.2, labels.GetRMSError()

# The region's range and its use set apart, as ParaView's properties set them: a range alone does
# not turn the region on; UseRegion meshes the range last set.
parts = adaptivert.vtkAdaptiveTetReducer()
parts.SetInputData(image)
parts.SetTargetTets(2000)
parts.SetRegionRange(0.5, 1.0)
assert not parts.GetUseRegion() and tuple(parts.GetRegion()) == (0.5, 1.0)
parts.SetUseRegion(True)
parts.Update()
assert parts.GetRegionVoxels() == reducer.GetRegionVoxels(), (parts.GetRegionVoxels(), reducer.GetRegionVoxels())
parts.SetUseRegion(False)
assert not parts.GetUseRegion()
print("SetRegionRange + SetUseRegion: the same region")
