"""pvbatch, on any number of ranks: reduce a CT with the plugin's reducer and draw it with 'Tet Ray
Cast Volume', or draw a mesh file; write the image, the mesh (.pvtu, one piece per rank) and, from
every rank, what it held: the extent its reducer reduced and was given, its tets, and its peak
memory before and after (VmHWM of /proc/self/status, kB).
    pv_pieces.py reduce VOLUME OUTDIR TETS     pv_pieces.py draw MESH OUTDIR"""
import json
import os
import sys

from paraview.simple import (AdaptiveTetReducer, OpenDataFile, ProgrammableFilter, SaveData, Sphere,
                             UpdatePipeline)

import art_pv

SIZE = (400, 400)
ERROR_BOUND = 0.04
# Run on every rank inside the pipeline: a programmable filter's script is executed by each.
RECORD = r"""
import json, os
from vtkmodules.vtkParallelCore import vtkMultiProcessController
c = vtkMultiProcessController.GetGlobalController()
rank = c.GetLocalProcessId() if c else 0
data = inputs[0].VTKObject
status = dict(l.split(':', 1) for l in open('/proc/self/status') if ':' in l)
rec = {'rank': rank, 'peak_kb': int(status['VmHWM'].split()[0]), 'rss_kb': int(status['VmRSS'].split()[0]),
       'cells': data.GetNumberOfCells(), 'bounds': list(data.GetBounds())}
fd = data.GetFieldData()
for name in ('piece_extent', 'input_extent', 'piece_target_tets', 'piece_target_error', 'total_tets', 'rms_error', 'weighted_rms_error', 'pieces',
             'scalar_range_min', 'scalar_range_max', 'target_error'):
    a = fd.GetArray(name)
    if a:
        rec[name] = [a.GetComponent(0, k) for k in range(a.GetNumberOfComponents())]
with open(os.path.join(%(dir)r, '%(tag)s-rank%%d.json' %% rank), 'w') as f:
    json.dump(rec, f)
output.ShallowCopy(data)
"""


def record_ranks(source, outdir, tag):
    """Runs RECORD on every rank (ParaView runs a programmable filter's script in this module's
    namespace, after a star import of numpy: the names here avoid numpy's)."""
    pf = ProgrammableFilter(Input=source)
    pf.Script = RECORD % {"dir": outdir, "tag": tag}
    pf.CopyArrays = 0
    UpdatePipeline(proxy=pf)


def main():
    # Locals: the programmable filters' star import lands in the module's namespace.
    mode, path, outdir = sys.argv[1:4]
    os.makedirs(outdir, exist_ok=True)
    n = art_pv.ranks()
    record_ranks(Sphere(), outdir, "baseline-%d" % n)
    if mode == "reduce":
        reader = OpenDataFile(path)
        array = reader.PointData.keys()[0]
        source = AdaptiveTetReducer(Input=reader)
        source.Scalars = ["POINTS", array]
        source.TargetTets = int(sys.argv[4])
        source.TransferFunctionWeighting = art_pv.opacity_function(array)
        record_ranks(source, outdir, "reduced-%d" % n)
        SaveData(os.path.join(outdir, "mesh-%d.pvtu" % n), proxy=source)
        # An error bound needs no sharing: each part meets it (plain L2, a fraction of the range).
        bound = AdaptiveTetReducer(Input=reader, TargetTets=0, MaxError=ERROR_BOUND, ErrorRelative=1)
        bound.Scalars = ["POINTS", array]
        record_ranks(bound, outdir, "bounded-%d" % n)
    else:
        source = OpenDataFile(path)
        array = source.PointData.keys()[0]
    view, display = art_pv.show_tets(source, array, SIZE)
    art_pv.frame_like_render(view, source.GetDataInformation().GetBounds(), SIZE)
    art_pv.screenshot(view, os.path.join(outdir, "%s-%d.png" % (mode, n)), SIZE)
    print(json.dumps({"ranks": n, "cells": source.GetDataInformation().GetNumberOfCells()}))


main()
