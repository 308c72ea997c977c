"""vtkTetRayCastMapper reports progress and honours the render window's abort check, as VTK's volume
mappers do: Start, Progress (0 .. 1, rising) and End events each frame; an abort leaves the last
whole image in place.

Needs a display (CI runs ctest under xvfb-run -a); without one it reports a skip (exit 77).
"""
import time

from mapper_scene import offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkCommand, vtkObject
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty

import adaptivert

vtkObject.GlobalWarningDisplayOff()

src = vtkRTAnalyticSource()
src.SetWholeExtent(-10, 10, -10, 10, -10, 10)
tri = vtkDataSetTriangleFilter()
tri.SetInputConnection(src.GetOutputPort())
tri.Update()

ctf = vtkColorTransferFunction()
ctf.AddRGBPoint(40, 0.1, 0.2, 1.0)
ctf.AddRGBPoint(280, 1.0, 0.1, 0.1)
otf = vtkPiecewiseFunction()
otf.AddPoint(40, 0.0)
otf.AddPoint(280, 0.5)
prop = vtkVolumeProperty()
prop.SetColor(ctf)
prop.SetScalarOpacity(otf)
prop.SetScalarOpacityUnitDistance(2.0)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(tri.GetOutput())
mapper.AutoAdjustSampleDistancesOff()
volume, ren, win = offscreen_scene(mapper, prop, 200, 160)
ren.ResetCamera()

events = []


def on_start(obj, event):
    events.append("start")


def on_end(obj, event):
    events.append("end")


@calldata_type(VTK_DOUBLE)
def on_progress(obj, event, fraction):
    events.append(fraction)


mapper.AddObserver(vtkCommand.VolumeMapperRenderStartEvent, on_start)
mapper.AddObserver(vtkCommand.VolumeMapperRenderProgressEvent, on_progress)
mapper.AddObserver(vtkCommand.VolumeMapperRenderEndEvent, on_end)

win.Render()
print("events of one frame:", events[:3], "...", events[-3:], f"({len(events)} in all)")
assert events[0] == "start" and events[-1] == "end", events
assert events.count("start") == 1 and events.count("end") == 1, events
fractions = events[1:-1]
assert len(fractions) >= 2, fractions
assert fractions[0] == 0.0 and fractions[-1] == 1.0, fractions
assert all(0.0 <= a <= b <= 1.0 for a, b in zip(fractions, fractions[1:])), fractions
whole = vtk_to_numpy(mapper.GetLastImage().GetPointData().GetScalars()).copy()
tets = mapper.GetLastTetsCrossed()
assert whole[:, 3].max() > 0.1 and tets > 0, (whole[:, 3].max(), tets)

# An interactor's abort check (a pending event) stops the next frame: it is not drawn, and the
# last whole frame stays, although the camera has moved.
aborts = []


def abort(obj, event):
    aborts.append(1)
    obj.SetAbortRender(1)


win.AddObserver(vtkCommand.AbortCheckEvent, abort)
ren.GetActiveCamera().Azimuth(40)
events.clear()
# vtkRenderWindow::CheckAbortStatus asks its observers at most every 0.2 s: right after the last
# frame's checks, a fast frame could end before the next one (the test failed one run in three).
time.sleep(0.25)
win.Render()
print("events of an aborted frame:", events)
assert aborts, "the mapper never asked the window whether to abort"
assert events[0] == "start" and events[-1] == "end", events
assert 1.0 not in events, events
kept = vtk_to_numpy(mapper.GetLastImage().GetPointData().GetScalars())
assert np.array_equal(kept, whole), "an aborted frame replaced the last image"
assert mapper.GetLastTetsCrossed() == tets

# Without the abort the moved camera gives a different whole frame.
win.RemoveObservers(vtkCommand.AbortCheckEvent)
win.Render()
moved = vtk_to_numpy(mapper.GetLastImage().GetPointData().GetScalars())
assert not np.array_equal(moved, whole)
print("ok")
