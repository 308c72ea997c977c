"""pvbatch: the triangle-grid locator where ParaView 5.11 takes a cell locator, Resample With
Dataset's Cell Locator list. A surface's point data resampled onto points near it (a finer sphere
just inside a coarse one, every point within 0.0031 of it, the tolerance 0.005) through 'Triangle
Grid Cell Locator' finds every point (ParaView's Static Cell Locator, searching only the bin of
the point, misses some) and, where both find one, gives the values the static locator gives, to
within what the field changes over the tolerance (another cell within it may be taken). An
unstructured volume source is refused: the locator holds surface cells only."""
import sys

from paraview import servermanager
from paraview.vtk import vtkOutputWindow
from vtkmodules.vtkCommonCore import vtkStringOutputWindow
from paraview.simple import Elevation, ResampleWithDataset, Sphere, Tetrahedralize, Wavelet

TOLERANCE = 0.005
SLACK = 0.5 * TOLERANCE  # the elevation field rises by 0.5 a unit length
# VTK's warnings, kept: a locator without VTK 9.2's FindCell is replaced by the data set's own
# search, with a warning ("Does not implement FindCell"), and the values would still come.
# (pvbatch's print goes to the same window: it is shown at the end.)
shown = vtkOutputWindow.GetInstance()
said = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(said)
coarse = Sphere(Radius=1.0, ThetaResolution=48, PhiResolution=48)
field = Elevation(Input=coarse, LowPoint=[0, 0, -1], HighPoint=[0, 0, 1])
fine = Sphere(Radius=0.999, ThetaResolution=97, PhiResolution=95)

resample = ResampleWithDataset(SourceDataArrays=field, DestinationMesh=fine)
locators = resample.GetProperty("CellLocator").Available
print("Resample With Dataset's cell locators:", locators)
if "Triangle Grid Cell Locator" not in locators:
    sys.exit("the triangle-grid locator is not offered")
resample.ComputeTolerance = 0
resample.Tolerance = TOLERANCE


def probe(locator):
    resample.CellLocator = locator
    resample.UpdatePipeline()
    data = servermanager.Fetch(resample)
    mask = data.GetPointData().GetArray("vtkValidPointMask")
    values = data.GetPointData().GetArray("Elevation")
    return [int(mask.GetTuple1(i)) for i in range(mask.GetNumberOfTuples())], \
        [values.GetTuple1(i) for i in range(values.GetNumberOfTuples())]


ours_mask, ours = probe("Triangle Grid Cell Locator")
resample.CellLocator.AcceleratorType = "Octree"
octree_mask, octree = probe(resample.CellLocator)
theirs_mask, theirs = probe("Static Cell Locator")
found = sum(theirs_mask)
print("points: %d, found by Static Cell Locator %d, by Triangle Grid (recursive grid) %d, (octree) %d"
      % (len(theirs_mask), found, sum(ours_mask), sum(octree_mask)))
fails = []
for name, mask, values in (("recursive grid", ours_mask, ours), ("octree", octree_mask, octree)):
    if sum(mask) != len(mask):
        fails.append("%s misses %d points within the tolerance" % (name, len(mask) - sum(mask)))
    if any(b and not a for a, b in zip(mask, theirs_mask)):
        fails.append("%s misses points the static locator finds" % name)
    worst = max(abs(a - b) for a, b, m in zip(values, theirs, theirs_mask) if m)
    print("%s: largest difference from the static locator's values %.2e (bound %.1e)" % (name, worst, SLACK))
    if worst > SLACK:
        fails.append("%s values differ by %.2e" % (name, worst))

# A volume is not a surface: the locator says so and finds nothing.
tets = Tetrahedralize(Input=Wavelet(WholeExtent=[-5, 5, -5, 5, -5, 5]))
volume = ResampleWithDataset(SourceDataArrays=tets, DestinationMesh=fine, CellLocator="Triangle Grid Cell Locator")
volume.UpdatePipeline()
data = servermanager.Fetch(volume)
hits = sum(int(data.GetPointData().GetArray("vtkValidPointMask").GetTuple1(i)) for i in range(data.GetNumberOfPoints()))
print("an unstructured volume source: %d points found" % hits)
if hits:
    fails.append("a volume source gave %d points" % hits)
vtkOutputWindow.SetInstance(shown)
print("\n".join(line for line in said.GetOutput().splitlines() if line.strip()))
if "Does not implement FindCell" in said.GetOutput():
    fails.append("VTK searched the data set itself: " + said.GetOutput().strip().splitlines()[0])
if fails:
    sys.exit("; ".join(fails))
print("ok")
