#!/usr/bin/env python3
"""Make the embedded default volume data/ct-head-128.mha (128 x 128 x 54 int16 HU).

Usage: /usr/bin/python3 data/make_default.py [INPUT.mha] [OUTPUT.mha]

INPUT defaults to ../shared/data/ct-head.mha (from the project root), the 256 x 256 x 108
CT head, or else to data/full/ct-head.mha made by `data/fetch ct-head`. Both hold the same
voxels; the fetched one has InVesalius' exact spacing 0.9570312 instead of 0.957, so from
it the output header (and checksum) differs in the 7th digit of spacing and origin.
OUTPUT defaults to data/ct-head-128.mha next to this script. The result is deterministic:
same input, same bytes.
"""
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED_IN = os.path.join(HERE, "..", "..", "shared", "data", "ct-head.mha")
FETCHED_IN = os.path.join(HERE, "full", "ct-head.mha")  # made by data/fetch ct-head
DEFAULT_OUT = os.path.join(HERE, "ct-head-128.mha")


def read(path):
    reader = vtk.vtkMetaImageReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit(f"make_default: cannot read {path}")
    return image


def shrink2(image):
    """2x2x2 block mean. Done in numpy rather than vtkImageShrink3D so the rounding is
    explicit (round half up, not truncation towards zero) and the geometry is exact."""
    nx, ny, nz = image.GetDimensions()
    if nx % 2 or ny % 2 or nz % 2:
        sys.exit(f"make_default: dimensions {nx}x{ny}x{nz} are not all even")
    a = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(nz, ny, nx).astype(np.int64)
    s = a.reshape(nz // 2, 2, ny // 2, 2, nx // 2, 2).sum(axis=(1, 3, 5))
    mean = np.floor_divide(s + 4, 8).astype(np.int16)  # floor((sum + 4) / 8) == round half up

    out = vtk.vtkImageData()
    out.SetDimensions(nx // 2, ny // 2, nz // 2)
    sp = image.GetSpacing()
    org = image.GetOrigin()
    # Each new voxel is the centre of 2x2x2 old ones: keeps the physical extent.
    out.SetSpacing(*(2 * s_ for s_ in sp))
    out.SetOrigin(*(o + 0.5 * s_ for o, s_ in zip(org, sp)))
    scalars = numpy_to_vtk(mean.ravel(), deep=True, array_type=vtk.VTK_SHORT)
    scalars.SetName("ct-hu")
    out.GetPointData().SetScalars(scalars)
    return out


def write(image, path):
    tmp = path + ".tmp.mha"  # .mha suffix: the writer picks single-file mode from it
    writer = vtk.vtkMetaImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(tmp)
    writer.SetCompression(True)
    writer.Write()
    os.replace(tmp, path)


def check(path, want_dims, want_spacing, want_origin, want_range):
    image = read(path)
    ok = (image.GetDimensions() == want_dims
          and np.allclose(image.GetSpacing(), want_spacing, rtol=0, atol=1e-6)
          and np.allclose(image.GetOrigin(), want_origin, rtol=0, atol=1e-6)
          and image.GetScalarRange() == want_range
          and image.GetScalarType() == vtk.VTK_SHORT)
    if not ok:
        sys.exit(f"make_default: {path} reads back wrong: dims {image.GetDimensions()} "
                 f"spacing {image.GetSpacing()} origin {image.GetOrigin()} range {image.GetScalarRange()}")


def main(argv):
    if len(argv) > 1 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return
    src = argv[1] if len(argv) > 1 else (SHARED_IN if os.path.exists(SHARED_IN) else FETCHED_IN)
    if not os.path.exists(src):
        sys.exit(f"make_default: {src} not found (run data/fetch ct-head, or pass INPUT.mha)")
    dst = argv[2] if len(argv) > 2 else DEFAULT_OUT
    full = read(src)
    small = shrink2(full)
    write(small, dst)
    check(dst, small.GetDimensions(), small.GetSpacing(), small.GetOrigin(), small.GetScalarRange())
    print(f"{os.path.relpath(dst)}: {'x'.join(map(str, small.GetDimensions()))} "
          f"spacing {' '.join('%.6g' % v for v in small.GetSpacing())} "
          f"origin {' '.join('%.6g' % v for v in small.GetOrigin())} "
          f"range {small.GetScalarRange()[0]:.0f}..{small.GetScalarRange()[1]:.0f} "
          f"{os.path.getsize(dst)} bytes")


if __name__ == "__main__":
    main(sys.argv)
