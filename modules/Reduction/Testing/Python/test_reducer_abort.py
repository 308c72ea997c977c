"""vtkAdaptiveTetReducer stops when a progress observer calls SetAbortExecute(1), as VTK's filters
do: both outputs come back empty, with no error, and a later run with the abort cleared reduces
again. The abort was ignored: the reduction ran on to its full budget. An aborted run after a
finished one leaves no figures of it behind (GetRMSError gave the earlier run's).
"""
import math
import os
import time

import adaptivert
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOImage import vtkMetaImageReader

source = os.environ.get("ART_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))
reader = vtkMetaImageReader()
reader.SetFileName(os.path.join(source, "data", "ct-head-128.mha"))
reducer = adaptivert.vtkAdaptiveTetReducer()
reducer.SetInputConnection(reader.GetOutputPort())
reducer.SetTargetTets(20000)
reducer.AddLevel(5000)
seen = []


def abort_early(caller, event):
    seen.append(caller.GetProgress())
    if caller.GetProgress() > 0.1:
        caller.SetAbortExecute(1)


errors = []
reducer.AddObserver(vtkCommand.ErrorEvent, lambda c, e: errors.append(e))
tag = reducer.AddObserver(vtkCommand.ProgressEvent, abort_early)
start = time.time()
reducer.Update()
print(f"aborted after {time.time() - start:.2f} s at progress {seen[-1]:.2f}: "
      f"{reducer.GetOutput().GetNumberOfCells()} tets, {reducer.GetOutputDataObject(1).GetNumberOfBlocks()} levels")
assert reducer.GetOutput().GetNumberOfCells() == 0, "the abort was ignored"
assert reducer.GetOutputDataObject(1).GetNumberOfBlocks() == 0
assert max(seen) < 0.9, seen  # it stopped, not finished
assert not errors, errors

reducer.RemoveObserver(tag)
reducer.SetAbortExecute(0)
reducer.Update()
tets = reducer.GetOutput().GetNumberOfCells()
print(f"run again: {tets} tets, {reducer.GetOutputDataObject(1).GetNumberOfBlocks()} levels")
assert 20000 <= tets < 20100, tets
assert reducer.GetOutputDataObject(1).GetNumberOfBlocks() == 2
assert reducer.GetRMSError() > 0, reducer.GetRMSError()

seen.clear()
reducer.AddObserver(vtkCommand.ProgressEvent, abort_early)
reducer.SetTargetTets(30000)
reducer.Update()
print(f"aborted again: {reducer.GetOutput().GetNumberOfCells()} tets, RMS {reducer.GetRMSError()}")
assert reducer.GetOutput().GetNumberOfCells() == 0
assert math.isnan(reducer.GetRMSError()) and math.isnan(reducer.GetMaxError()), reducer.GetRMSError()
print("ok")
