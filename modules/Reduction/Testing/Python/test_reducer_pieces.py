"""vtkAdaptiveTetReducer under piece requests (a parallel writer, ParaView in parallel).

The reduction needs the whole volume and makes one mesh: piece 0 holds it, the other pieces are
empty, so the pieces add up to the mesh of an ordinary Update. Before, the piece request went on
upstream beside the whole extent the reducer asked for: an image source split its extent and each
piece was a reduction of one slab with the whole budget (2 pieces: twice the tets, seams that do
not match), and behind a reader that cannot split each piece was a copy of the whole mesh.
"""
import os
import tempfile

import adaptivert
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkMetaImageReader
from vtkmodules.vtkIOParallelXML import vtkXMLPUnstructuredGridWriter
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader

source = os.environ.get("ART_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))
wavelet = vtkRTAnalyticSource()
wavelet.SetWholeExtent(0, 20, 0, 20, 0, 20)
ct = vtkMetaImageReader()
ct.SetFileName(os.path.join(source, "data", "ct-head-128.mha"))

for label, src in (("wavelet (splits its extent)", wavelet), ("ct-head-128.mha (cannot split)", ct)):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputConnection(src.GetOutputPort())
    r.SetTargetTets(2000)
    r.AddLevel(500)
    r.UpdatePiece(0, 1, 0)
    whole = r.GetOutput().GetNumberOfCells()
    whole_extent = r.GetInputDataObject(0, 0).GetExtent()
    counts = []
    for piece in range(3):
        r.UpdatePiece(piece, 3, 1)
        counts.append(r.GetOutput().GetNumberOfCells())
        assert r.GetInputDataObject(0, 0).GetExtent() == whole_extent, (piece, r.GetInputDataObject(0, 0).GetExtent())
        assert r.GetOutputDataObject(1).GetNumberOfBlocks() == (2 if piece == 0 else 0), piece
    print(f"{label}: whole {whole} tets, pieces {counts}")
    assert counts == [whole, 0, 0], counts

    # A parallel writer's pieces read back as the one mesh.
    with tempfile.TemporaryDirectory() as d:
        w = vtkXMLPUnstructuredGridWriter()
        w.SetInputConnection(r.GetOutputPort())
        w.SetFileName(os.path.join(d, "mesh.pvtu"))
        w.SetNumberOfPieces(2)
        w.SetStartPiece(0)
        w.SetEndPiece(1)
        assert w.Write()
        rd = vtkXMLPUnstructuredGridReader()
        rd.SetFileName(os.path.join(d, "mesh.pvtu"))
        rd.Update()
        print(f"  .pvtu of 2 pieces reads back as {rd.GetOutput().GetNumberOfCells()} tets")
        assert rd.GetOutput().GetNumberOfCells() == whole
print("ok")
