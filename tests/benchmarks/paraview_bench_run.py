"""pvbatch, on any number of ranks (paraview_bench.py starts it): one configuration of the ParaView
benchmark. Reduces VOLUME to TETS weighted by the ct-skin-bone transfer function REPEATS times,
then draws the last mesh with 'Tet Ray Cast Volume' (a warm-up frame, then FRAMES frames, the
camera turned by a degree each); writes, from every rank, its part, tets, reduction seconds and
peak memory (VmHWM) before, after the reductions and after the frames, and from rank 0 the wall
times and the first frame's image.
    paraview_bench_run.py VOLUME TETS REPEATS FRAMES OUTDIR"""
import json
import os
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "paraview", "Testing"))

from paraview.simple import (AdaptiveTetReducer, Delete, OpenDataFile, ProgrammableFilter, Render, Sphere,  # noqa: E402
                             UpdatePipeline)

import art_pv  # noqa: E402

SIZE = (500, 500)
RECORD = r"""
import json, os
from vtkmodules.vtkParallelCore import vtkMultiProcessController
c = vtkMultiProcessController.GetGlobalController()
rank = c.GetLocalProcessId() if c else 0
data = inputs[0].VTKObject
status = dict(l.split(':', 1) for l in open('/proc/self/status') if ':' in l)
rec = {'rank': rank, 'peak_kb': int(status['VmHWM'].split()[0]), 'cells': data.GetNumberOfCells()}
fd = data.GetFieldData()
for name in ('piece_extent', 'input_extent', 'piece_target_tets', 'build_seconds', 'piece_pilot_seconds',
             'total_tets', 'rms_error', 'weighted_rms_error'):
    a = fd.GetArray(name)
    if a:
        rec[name] = [a.GetComponent(0, k) for k in range(a.GetNumberOfComponents())]
with open(os.path.join(%(dir)r, '%(tag)s-rank%%d.json' %% rank), 'w') as f:
    json.dump(rec, f)
output.ShallowCopy(data)
"""


def record_ranks(source, outdir, tag):
    """Runs RECORD on every rank (a programmable filter's script runs in this module's namespace
    after a star import of numpy: the names here avoid numpy's)."""
    pf = ProgrammableFilter(Input=source)
    pf.Script = RECORD % {"dir": outdir, "tag": tag}
    pf.CopyArrays = 0
    UpdatePipeline(proxy=pf)
    Delete(pf)


def main():
    volume, tets, repeats, frames, outdir = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
    os.makedirs(outdir, exist_ok=True)
    record_ranks(Sphere(), outdir, "baseline")
    reader = OpenDataFile(volume)
    array = reader.PointData.keys()[0]
    weights = art_pv.opacity_function(array)
    reduce_seconds = []
    reducer = None
    for r in range(repeats):
        if reducer is not None:
            Delete(reducer)
        reducer = AdaptiveTetReducer(Input=reader, TargetTets=tets)
        reducer.Scalars = ["POINTS", array]
        reducer.TransferFunctionWeighting = weights
        t0 = time.perf_counter()
        record_ranks(reducer, outdir, "reduce%d" % r)
        reduce_seconds.append(time.perf_counter() - t0)
    view, display = art_pv.show_tets(reducer, array, SIZE)
    art_pv.frame_like_render(view, reader.GetDataInformation().GetBounds(), SIZE)
    art_pv.screenshot(view, os.path.join(outdir, "frame.png"), SIZE)
    camera = view.GetActiveCamera()
    render_seconds = []
    for f in range(frames):
        camera.Azimuth(1.0)
        t0 = time.perf_counter()
        Render(view)
        render_seconds.append(time.perf_counter() - t0)
    record_ranks(Sphere(ThetaResolution=9), outdir, "rendered")
    json.dump({"ranks": art_pv.ranks(), "reduce_seconds": reduce_seconds, "render_seconds": render_seconds,
               "tets": reducer.GetDataInformation().GetNumberOfCells()}, open(os.path.join(outdir, "times.json"), "w"))


main()
