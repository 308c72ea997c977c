"""pvbatch, a plugin built with AdaptiveRT::Meshing: the reducer's region and label-map properties
(AdaptiveRTMeshing.xml) mesh what `adaptivert reduce --region / --labels --values` meshes, and
'Tet Ray Cast Volume' draws the label mesh's values inside each label's hue (Label Coloring).

tests/data/meshing/halves-24.mha holds label 1 (x in 4 .. 11) beside label 2 (x in 12 .. 19);
halves-24-ramp.mha the values 10 z (z index 0 .. 23)."""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import AdaptiveTetReducer, GetColorTransferFunction, GetOpacityTransferFunction, Hide, \
    OpenDataFile, Render
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

import art_pv

DATA = os.path.join(art_pv.SOURCE, "tests", "data", "meshing")
out = os.path.join(art_pv.OUTPUT, "pv-regions")
os.makedirs(out, exist_ok=True)
fails = []


def expect(what, ok):
    print("%-78s %s" % (what, "ok" if ok else "FAILED"))
    if not ok:
        fails.append(what)


labels = OpenDataFile(os.path.join(DATA, "halves-24.mha"))
ramp = OpenDataFile(os.path.join(DATA, "halves-24-ramp.mha"))
reducer = AdaptiveTetReducer(Input=labels)
for name in ("Values", "UseRegion", "RegionRange", "Labels", "Background", "MinimumIslandVoxels", "CompareWholeBox"):
    expect("property " + name, name in reducer.ListProperties())

# Labels with the ramp's values (input port 1).
reducer.Values = ramp
reducer.Labels = 1
reducer.TargetTets = 2000
reducer.UpdatePipeline()
grid = servermanager.Fetch(reducer)
label = grid.GetCellData().GetArray("label")
values = grid.GetPointData().GetScalars()
expect("label mesh: %d tets, cell array 'label'" % grid.GetNumberOfCells(), label is not None and grid.GetNumberOfCells() > 500)
if label is not None and values is not None:
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    worst = np.abs(vtk_to_numpy(values) - 10 * pts[:, 2]).max()
    expect("  labels %s, values within %.2f of 10 z (bound 5)" % (sorted(set(vtk_to_numpy(label))), worst),
           sorted(set(vtk_to_numpy(label))) == [1, 2] and worst < 5)
    expect("  the values' window recorded", grid.GetFieldData().GetArray("source_window") is not None)
else:
    expect("  point values carried", False)

# A region of the ramp: z 10 .. 23, fitted exactly.
region = AdaptiveTetReducer(Input=ramp)
region.UseRegion = 1
region.RegionRange = [100, 230]
region.TargetTets = 1000
region.UpdatePipeline()
region.UpdatePropertyInformation()
rgrid = servermanager.Fetch(region)
zs = vtk_to_numpy(rgrid.GetPoints().GetData())[:, 2] if rgrid.GetNumberOfPoints() else np.array([0.0])
rms = rgrid.GetFieldData().GetArray("rms_error")
voxels = region.GetProperty("RegionVoxels").GetData()
expect("region 100:230: %d tets, z %.2f .. %.2f, %s voxels (24 x 24 x 14 = 8064)" % (
    rgrid.GetNumberOfCells(), zs.min(), zs.max(), voxels), rgrid.GetNumberOfCells() > 200 and zs.min() > 9.9 and voxels == 8064)
expect("  RMS %.3g inside the region (bound 1e-3)" % (rms.GetValue(0) if rms else -1), rms is not None and rms.GetValue(0) < 1e-3)


def side_colours(view, name):
    png = art_pv.screenshot(view, os.path.join(out, name + ".png"), (160, 160))
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    w, h = r.GetOutput().GetDimensions()[:2]
    img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3] / 255.0
    band = img[h // 3: 2 * h // 3]
    return band[:, w // 5: 2 * w // 5].mean((0, 1)), band[:, 3 * w // 5: 4 * w // 5].mean((0, 1))


# Drawn through the caster, coloured by the values with a grey ramp: label 1 orange, label 2
# green (Values In Labels, the default); the grey ramp alone on both sides under Off.
view, display = art_pv.show_tets(reducer, "MetaImage", (160, 160))
lut = GetColorTransferFunction("MetaImage")
lut.RGBPoints = [0, 0.2, 0.2, 0.2, 230, 1, 1, 1]
GetOpacityTransferFunction("MetaImage").Points = [0, 0.5, 0.5, 0, 230, 0.5, 0.5, 0]
Render(view)
view.CameraFocalPoint = [11.5, 11.5, 11.5]
view.CameraPosition = [11.5, -40, 11.5]
view.CameraViewUp = [0, 0, 1]
view.CameraParallelProjection = 1
view.CameraParallelScale = 10
expect("display property LabelColoring, default 'Values In Labels'",
       "LabelColoring" in display.ListProperties() and display.LabelColoring == "Values In Labels")
left, right = side_colours(view, "values-in-labels")
print("values in labels: left %s right %s" % (left.round(3), right.round(3)))
expect("  label 1 orange (r > g > b), label 2 green (g > r, g > b)",
       left[0] > left[1] > left[2] + 0.1 and right[1] > right[0] + 0.1 and right[1] > right[2] + 0.1)
display.LabelColoring = "Off"
left, right = side_colours(view, "off")
print("off: left %s right %s" % (left.round(3), right.round(3)))
expect("  Off: the grey ramp on both sides", np.abs(left - right).max() < 0.03 and np.ptp(left) < 0.03)
Hide(reducer, view)
if fails:
    sys.exit("failed: " + "; ".join(fails))
print("ok")
