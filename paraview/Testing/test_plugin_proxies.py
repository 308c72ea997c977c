"""pvbatch loads the plugin (PV_PLUGIN_PATH): the filter, the representation type and the cell
locator are there under their documented names (docs/paraview.md), with the properties a user sets; the filter's
Levels output holds a block per level."""
import sys

from paraview import servermanager
from paraview.simple import AdaptiveTetReducer, OpenDataFile, ResampleWithDataset, Show

import art_pv

fails = []


def expect(what, ok):
    print("%-70s %s" % (what, "ok" if ok else "MISSING"))
    if not ok:
        fails.append(what)


pxm = servermanager.ProxyManager()
filt = pxm.GetPrototypeProxy("filters", "AdaptiveTetReducer")
expect("filter AdaptiveTetReducer", filt is not None)
expect("  labelled 'Adaptive Tet Reducer'", filt is not None and filt.GetXMLLabel() == "Adaptive Tet Reducer")
reader = OpenDataFile(art_pv.DEFAULT_CT)
reducer = AdaptiveTetReducer(Input=reader)
for name in ("TargetTets", "MaxError", "ErrorMetric", "TransferFunctionWeighting", "IsoValues", "Refinement",
             "Levels", "RelocateVertices", "Scalars"):
    expect("  property " + name, name in reducer.ListProperties())
expect("  Refinement choices from Bisection, Edge Split",
       reducer.GetProperty("Refinement").Available[:2] == ["Bisection", "Edge Split"])

reducer.Scalars = ["POINTS", "MetaImage"]
reducer.TargetTets = 3000
reducer.Levels = [500, 1500]
reducer.UpdatePipeline()
tets = reducer.GetDataInformation(0).GetNumberOfCells()
blocks = reducer.GetDataInformation(1).DataInformation.GetNumberOfDataSets()
expect("  %d tets for a budget of 3000" % tets, abs(tets - 3000) <= 30)
expect("  Levels output: %d blocks for levels 500, 1500 and the final grid" % blocks, blocks == 3)

display = Show(reducer)
types = display.GetProperty("Representation").Available
expect("representation type 'Tet Ray Cast Volume' of an unstructured grid", "Tet Ray Cast Volume" in types)
expect("  the reducer's default display", display.Representation == "Tet Ray Cast Volume")
for name in ("EarlyRayTermination", "Integrator", "IsoValues", "IsoOpacity", "ImageSampleDistance",
             "AutoAdjustSampleDistances", "ScalarOpacityFunction", "ScalarOpacityUnitDistance"):
    expect("  display property " + name, name in display.ListProperties())
expect("  Integrator choices Exact, Trapezoid", display.GetProperty("Integrator").Available == ["Exact", "Trapezoid"])

resample = ResampleWithDataset(SourceDataArrays=reducer, DestinationMesh=reader)
expect("cell locator 'Triangle Grid Cell Locator' in Resample With Dataset",
       "Triangle Grid Cell Locator" in resample.GetProperty("CellLocator").Available)
if fails:
    sys.exit("missing: " + "; ".join(fails))
print("ok")
