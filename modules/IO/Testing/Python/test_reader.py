"""adaptivert.vtkAdaptiveRTReader reads every format the CLI reads, as the CLI does, and refuses
bad files with one line and no crash. Each format's file is written here (with VTK's writers
where it has one), read through the reader, and compared with VTK's own reader of the format."""
import glob
import os
import struct
import sys
import tempfile

import adaptivert
import vtk

work = tempfile.mkdtemp(prefix="art-reader-")
src = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "..")


def wavelet(kind=vtk.VTK_SHORT):
    s = vtk.vtkRTAnalyticSource()
    s.SetWholeExtent(0, 7, 0, 5, 0, 4)
    s.SetMaximum(255)
    c = vtk.vtkImageCast()
    c.SetInputConnection(s.GetOutputPort())
    c.SetOutputScalarType(kind)
    c.Update()
    img = vtk.vtkImageData()
    img.DeepCopy(c.GetOutput())
    img.SetSpacing(0.5, 0.75, 2.0)
    return img


def read(path, **settings):
    r = adaptivert.vtkAdaptiveRTReader()
    r.SetFileName(path)
    for k, v in settings.items():
        getattr(r, "Set" + k)(*v) if isinstance(v, tuple) else getattr(r, "Set" + k)(v)
    r.Update()
    return r


def values(img):
    a = img.GetPointData().GetScalars()
    return [a.GetTuple1(i) for i in range(a.GetNumberOfTuples())]


def same_volume(ours, theirs, name):
    assert ours.GetDimensions() == theirs.GetDimensions(), (name, ours.GetDimensions(), theirs.GetDimensions())
    for a in range(3):
        assert abs(ours.GetSpacing()[a] - theirs.GetSpacing()[a]) < 1e-6, (name, ours.GetSpacing(), theirs.GetSpacing())
    assert values(ours) == values(theirs), name


def vtk_read(cls, path, **set_up):
    r = cls()
    r.SetFileName(path)
    for k, v in set_up.items():
        getattr(r, k)(*v)
    r.Update()
    return r.GetOutputDataObject(0)


def write(writer, data, name, **set_up):
    path = os.path.join(work, name)
    writer.SetInputData(data)
    writer.SetFileName(path)
    for k, v in set_up.items():
        getattr(writer, k)(*v)
    writer.Write()
    return path


img = wavelet()
checked = []
# Volumes, against VTK's reader of each format (the placement is VTK's in the vtk frame).
for name, writer, reader in (
        ("v.mha", vtk.vtkMetaImageWriter(), vtk.vtkMetaImageReader),
        ("v.vti", vtk.vtkXMLImageDataWriter(), vtk.vtkXMLImageDataReader),
        ("v.nii", vtk.vtkNIFTIImageWriter(), vtk.vtkNIFTIImageReader),
        ("v.nii.gz", vtk.vtkNIFTIImageWriter(), vtk.vtkNIFTIImageReader),
        ("v.hdr", vtk.vtkNIFTIImageWriter(), vtk.vtkNIFTIImageReader),
        ("v.mnc", vtk.vtkMINCImageWriter(), vtk.vtkMINCImageReader),
        ("v.vtk", vtk.vtkStructuredPointsWriter(), vtk.vtkStructuredPointsReader)):
    path = write(writer, img, name)
    r = read(path, Frame="vtk")
    assert not r.GetErrorMessage(), r.GetErrorMessage()
    out = r.GetOutputDataObject(0)
    assert out.IsA("vtkImageData"), (name, out.GetClassName())
    same_volume(out, vtk_read(reader, path), name)
    assert out.GetFieldData().GetAbstractArray("Frame").GetValue(0) == "VTK reader", name
    assert out.GetFieldData().GetArray("IndexToWorld").GetNumberOfComponents() == 16, name
    checked.append(name)
nrrd = os.path.join(work, "v.nrrd")
with open(nrrd, "wb") as f:
    f.write(b"NRRD0004\ntype: short\ndimension: 3\nsizes: 8 6 5\nspacings: 0.5 0.75 2\nencoding: raw\nendian: little\n\n")
    f.write(struct.pack("<240h", *[int(v) for v in values(img)]))
# (vtk.vtkNrrdReader is vtkPNrrdReader here, which fails outside an MPI run: the voxels written
# are the reference.)
same_volume(read(nrrd).GetOutputDataObject(0), img, "v.nrrd")
checked.append("v.nrrd")
tiff = write(vtk.vtkTIFFWriter(), wavelet(vtk.VTK_UNSIGNED_CHAR), "v.tif", SetFileDimensionality=(3,))
same_volume(read(tiff).GetOutputDataObject(0),
            vtk_read(vtk.vtkTIFFReader, tiff), "v.tif")
checked.append("v.tif")
os.makedirs(os.path.join(work, "png"))
png = vtk.vtkPNGWriter()
png.SetInputData(wavelet(vtk.VTK_UNSIGNED_CHAR))
png.SetFilePattern(os.path.join(work, "png", "s%03d.png"))
png.Write()
stack = read(os.path.join(work, "png"), RawSpacing=(0.5, 0.75, 2.0)).GetOutputDataObject(0)
same_volume(stack, wavelet(vtk.VTK_UNSIGNED_CHAR), "png stack")
checked.append("png stack")
raw = os.path.join(work, "v.raw")
with open(raw, "wb") as f:
    f.write(struct.pack(">240h", *[int(v) for v in values(img)]))
r = read(raw, RawDimensions=(8, 6, 5), RawScalarType="int16", RawSpacing=(0.5, 0.75, 2.0), RawBigEndian=True)
assert not r.GetErrorMessage(), r.GetErrorMessage()
same_volume(r.GetOutputDataObject(0), img, "raw")
checked.append("raw")
# DICOM folder: the patient placement the CLI uses.
dicom = read(os.path.join(src, "tests", "data", "dicom")).GetOutputDataObject(0)
assert dicom.GetDimensions() == (16, 12, 4), dicom.GetDimensions()
checked.append("DICOM")

# Meshes and surfaces, against VTK's readers.
tri = vtk.vtkDataSetTriangleFilter()
tri.SetInputData(img)
tri.Update()
sphere = vtk.vtkSphereSource()
sphere.Update()
for name, writer, data, reader in (
        ("m.vtu", vtk.vtkXMLUnstructuredGridWriter(), tri.GetOutput(), vtk.vtkXMLUnstructuredGridReader),
        ("m.vtk", vtk.vtkUnstructuredGridWriter(), tri.GetOutput(), vtk.vtkUnstructuredGridReader),
        ("s.vtp", vtk.vtkXMLPolyDataWriter(), sphere.GetOutput(), vtk.vtkXMLPolyDataReader),
        ("s.ply", vtk.vtkPLYWriter(), sphere.GetOutput(), vtk.vtkPLYReader),
        ("s.stl", vtk.vtkSTLWriter(), sphere.GetOutput(), vtk.vtkSTLReader),
        ("s.obj", vtk.vtkOBJWriter(), sphere.GetOutput(), vtk.vtkOBJReader),
        ("s.facet", vtk.vtkFacetWriter(), sphere.GetOutput(), vtk.vtkFacetReader)):
    path = write(writer, data, name)
    out = read(path).GetOutputDataObject(0)
    theirs = vtk_read(reader, path)
    assert out.GetNumberOfCells() == theirs.GetNumberOfCells(), (name, out.GetNumberOfCells(), theirs.GetNumberOfCells())
    assert out.GetFieldData().GetAbstractArray("Frame").GetValue(0) == "file coordinates", name
    checked.append(name)

# Bad files: an error message naming the file, an empty output, no crash.
corpus = sorted(f for f in glob.glob(os.path.join(src, "tests", "data", "corpus", "*")) if not f.endswith(".py"))
assert len(corpus) >= 10, corpus
errors = vtk.vtkFileOutputWindow()  # VTK's error reports go to a file, not the test's output
errors.SetFileName(os.path.join(work, "vtk-errors.txt"))
vtk.vtkOutputWindow.SetInstance(errors)
for f in corpus + [os.path.join(work, "missing.mha")]:
    r = adaptivert.vtkAdaptiveRTReader()
    r.SetFileName(f)
    r.Update()
    message = r.GetErrorMessage()
    assert os.path.basename(f) + ": " in message and "\n" not in message, (f, message)
    assert r.GetOutputDataObject(0).GetNumberOfPoints() == 0, f
print("read %d formats against VTK's readers; %d bad files refused" % (len(checked), len(corpus) + 1))
