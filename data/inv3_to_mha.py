#!/usr/bin/env python3
"""Turn an unpacked InVesalius project (.inv3) into a zlib-compressed MetaImage volume.

Usage: inv3_to_mha.py DIR OUT.mha      DIR holds main.plist and the matrix file it names
       inv3_to_mha.py --fingerprint FILE.mha

--fingerprint prints one line with the geometry and the sha256 of the decoded voxels.
data/fetch uses it to accept an .mha whose bytes differ from the pinned checksum only
because another VTK or zlib wrote it (the voxels and geometry are what matter).
"""
import hashlib
import os
import plistlib
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def convert(folder, dst):
    with open(os.path.join(folder, "main.plist"), "rb") as fh:
        meta = plistlib.load(fh)
    m = meta["matrix"]
    nz, ny, nx = m["shape"]  # numpy order, x fastest on disk
    dtype = np.dtype(m["dtype"]).newbyteorder("<")
    raw = np.fromfile(os.path.join(folder, m["filename"]), dtype=dtype)
    if raw.size != nx * ny * nz:
        sys.exit(f"inv3_to_mha: {m['filename']} has {raw.size} values, main.plist says {nx}x{ny}x{nz}")
    # InVesalius keeps rows top-down (image order); VTK's y axis points up, so flip rows.
    # This matches ../shared/data/ct-head.mha voxel for voxel.
    vol = np.ascontiguousarray(raw.reshape(nz, ny, nx)[:, ::-1, :]).astype(np.int16)

    image = vtk.vtkImageData()
    image.SetDimensions(nx, ny, nz)
    image.SetSpacing(*(float(s) for s in meta["spacing"]))  # the project's own, 0.9570312 0.9570312 1.5
    image.SetOrigin(0.0, 0.0, 0.0)  # .inv3 format 1 stores no origin
    scalars = numpy_to_vtk(vol.ravel(), deep=True, array_type=vtk.VTK_SHORT)
    scalars.SetName("ct-hu")
    image.GetPointData().SetScalars(scalars)

    writer = vtk.vtkMetaImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(dst)  # caller passes a temp name ending in .mha (single-file mode)
    writer.SetCompression(True)
    writer.Write()
    print(f"{meta.get('name', '?')}: {nx}x{ny}x{nz} spacing {' '.join('%.7g' % s for s in meta['spacing'])} "
          f"range {vol.min()}..{vol.max()}")


def fingerprint(path):
    reader = vtk.vtkMetaImageReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        return "unreadable"
    voxels = vtk_to_numpy(scalars).astype("<i2" if image.GetScalarType() == vtk.VTK_SHORT else "<f8")
    fmt = lambda v: ",".join("%.7g" % x for x in v)
    return (f"dims={'x'.join(map(str, image.GetDimensions()))} spacing={fmt(image.GetSpacing())} "
            f"origin={fmt(image.GetOrigin())} type={image.GetScalarTypeAsString()} "
            f"voxels={hashlib.sha256(voxels.tobytes()).hexdigest()}")


def main(argv):
    if len(argv) == 3 and argv[1] == "--fingerprint":
        print(fingerprint(argv[2]))
    elif len(argv) == 3 and not argv[1].startswith("-"):
        convert(argv[1], argv[2])
    else:
        sys.exit(__doc__.strip())


if __name__ == "__main__":
    main(sys.argv)
