#!/usr/bin/env python3
"""Writes nifti-radiological.nii: a 4 x 3 x 2 int16 NIfTI-1 in radiological order (x flipped by
its sform, code 1: scanner), voxel (i, j, k) = i + 10 j + 100 k, written byte by byte so the
header is exactly this; and nifti-4d.nii, the same with 5 volumes (dim[4] = 5) and no qform or
sform. No third-party modules."""
import os
import struct

hdr = bytearray(352)
struct.pack_into("<i", hdr, 0, 348)
struct.pack_into("<8h", hdr, 40, 3, 4, 3, 2, 1, 1, 1, 1)  # dim
struct.pack_into("<hh", hdr, 70, 4, 16)  # datatype int16, bitpix
struct.pack_into("<8f", hdr, 76, 1, 2, 3, 4, 1, 1, 1, 1)  # pixdim (qfac 1)
struct.pack_into("<f", hdr, 108, 352)  # vox_offset
hdr[123] = 2  # millimetres
struct.pack_into("<hh", hdr, 252, 0, 1)  # qform_code, sform_code
struct.pack_into("<12f", hdr, 280, -2, 0, 0, 10, 0, 3, 0, 20, 0, 0, 4, 30)  # srow_x, y, z
hdr[344:348] = b"n+1\0"
data = b"".join(struct.pack("<h", i + 10 * j + 100 * k) for k in range(2) for j in range(3) for i in range(4))
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "nifti-radiological.nii"), "wb") as f:
    f.write(bytes(hdr) + data)
struct.pack_into("<8h", hdr, 40, 4, 4, 3, 2, 5, 1, 1, 1)  # a fourth dimension of 5 volumes
struct.pack_into("<hh", hdr, 252, 0, 0)  # no qform, no sform
with open(os.path.join(here, "nifti-4d.nii"), "wb") as f:
    f.write(bytes(hdr) + b"".join(struct.pack("<h", t * 1000 + v) for t in range(5) for v in range(24)))
