#!/usr/bin/python3
"""Writes the regression corpus of bad files beside this script: each is a small file that VTK
9.1's readers crashed on, hung on or read silently wrong, and that every loader (the CLI, the
viewer, vtkAdaptiveRTReader) must refuse with one line naming the file and the cause.
The fuzzing harness (tests/fuzz) adds what it finds here. Run: /usr/bin/python3 make_corpus.py"""
import os
import re
import struct

import vtk

here = os.path.dirname(os.path.abspath(__file__))


def path(name):
    return os.path.join(here, name)


def wavelet(n=4):
    src = vtk.vtkRTAnalyticSource()
    src.SetWholeExtent(0, n - 1, 0, n - 1, 0, n - 1)
    src.Update()
    return src.GetOutput()


def tets():
    tri = vtk.vtkDataSetTriangleFilter()
    tri.SetInputData(wavelet(3))
    tri.Update()
    return tri.GetOutput()


def write_xml(writer, data, name, mode):
    writer.SetInputData(data)
    writer.SetFileName(path(name))
    getattr(writer, "SetDataModeTo" + mode)()
    if mode == "Appended":
        writer.EncodeAppendedDataOff()
        writer.SetCompressorTypeToNone()
    writer.Write()
    with open(path(name), "rb") as f:
        return f.read()


def save(name, data):
    with open(path(name), "wb") as f:
        f.write(data)


# NRRD: dimension 0 and 17 segfaulted vtkNrrdReader.
for d in (0, 17):
    save("nrrd-dimension-%d.nrrd" % d, b"NRRD0004\ntype: float\ndimension: %d\nsizes: 4 4 4\nencoding: raw\n\n" % d
         + bytes(256))
# .vtu: a negative count, and elements nested far deeper than any VTK file.
text = write_xml(vtk.vtkXMLUnstructuredGridWriter(), tets(), "vtu-negative-cells.vtu", "Ascii").decode()
save("vtu-negative-cells.vtu", re.sub(r'NumberOfCells="\d+"', 'NumberOfCells="-5"', text).encode())
save("vtu-nested.vtu", b'<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1"><UnstructuredGrid>'
     + b"<a>" * 1000 + b"</a>" * 1000 + b"</UnstructuredGrid></VTKFile>\n")
# A connectivity naming vertex 1e9.
i = text.index('Name="connectivity"')
j = text.index(">", i) + 1
m = re.search(r"\d+", text[j:])
save("vtu-far-vertex.vtu", (text[: j + m.start()] + "1000000000" + text[j + m.end():]).encode())
# Appended .vti cut short, and a NaN spacing.
vti = write_xml(vtk.vtkXMLImageDataWriter(), wavelet(), "vti-cut.vti", "Appended")
save("vti-cut.vti", vti[: len(vti) * 9 // 10])
save("vti-nan-spacing.vti", re.sub(rb'Spacing="[^"]*"', b'Spacing="nan nan nan"', vti))
# A binary .vtu cut by a thousandth.
vtu = write_xml(vtk.vtkXMLUnstructuredGridWriter(), tets(), "vtu-cut.vtu", "Binary")
save("vtu-cut.vtu", vtu[: len(vtu) - max(1, len(vtu) // 1000)])
# Legacy files cut short, binary and text.
for name, writer, data, binary in (("legacy-volume-cut.vtk", vtk.vtkStructuredPointsWriter(), wavelet(), True),
                                   ("legacy-mesh-cut.vtk", vtk.vtkUnstructuredGridWriter(), tets(), False)):
    writer.SetInputData(data)
    writer.SetFileName(path(name))
    if binary:
        writer.SetFileTypeToBinary()
    writer.Write()
    with open(path(name), "rb") as f:
        b = f.read()
    save(name, b[: len(b) * 7 // 10])
# MetaImage: MET_CHAR over float data.
save("mha-char-over-float.mha", b"ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = MET_CHAR\n"
     b"ElementDataFile = LOCAL\n" + struct.pack("<64f", *range(64)))
# MetaImage: a header MetaIO rejects (it printed its own lines before ours).
save("mha-bad-ndims.mha", b"ObjectType = Image\nNDims = 7x\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
     b"ElementDataFile = LOCAL\n" + bytes(8))
# MetaImage: ElementSpacing before NDims, and text voxels too few (MetaIO printed its own lines).
save("mha-spacing-before-ndims.mha", b"ObjectType = Image\nElementSpacing = 1 1 1\nNDims = 3\nDimSize = 2 2 2\n"
     b"ElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + bytes(8))
save("mha-text-short.mha", b"ObjectType = Image\nNDims = 3\nBinaryData = False\nDimSize = 2 2 2\n"
     b"ElementType = MET_UCHAR\nElementDataFile = LOCAL\n1 2 3\n")
# NIfTI: pixdim 0 without an sform.
h = bytearray(352)
struct.pack_into("<i", h, 0, 348)
struct.pack_into("<8h", h, 40, 3, 4, 4, 4, 1, 1, 1, 1)
struct.pack_into("<hh", h, 70, 2, 8)
struct.pack_into("<8f", h, 76, 1, 1, 0, 1, 1, 1, 1, 1)
struct.pack_into("<f", h, 108, 352)
h[344:348] = b"n+1\0"
save("nifti-pixdim-0.nii", bytes(h) + bytes(64))
# An SLC whose run overruns its slice.
slc = b"11111 4 4 2 8 1 1 1 0 0 0 1\n1 1 X\0\0\0"
for _ in range(2):
    runs = b"\x7f\x05\x00"  # a repeat of 127 voxels in a 16-voxel slice
    slc += b"%d X" % len(runs) + runs
save("slc-overrun.slc", slc)
# An MRC shorter than its sizes.
mrc = bytearray(1024)
struct.pack_into("<4i", mrc, 0, 16, 16, 16, 2)
save("mrc-cut.mrc", bytes(mrc) + bytes(100))
# Binary bytes in a header line (they were echoed into the error).
save("mha-binary-header.mha", b"Obj\x01\x02\x1b[31m\n\xff\xfe = 3\n" + bytes(10))
