#!/usr/bin/env python3
"""Writes the bad NIfTI-1 files beside this script (no third-party modules): datatype-1234.nii
(an unknown datatype code: vtkNIFTIImageReader segfaulted), nan-spacing.nii (pixdim[1] NaN: a NaN
spacing), huge-sizes.nii (30000^3 voxels in a 400-byte file: 'out of memory'). Run once."""
import os
import struct

here = os.path.dirname(os.path.abspath(__file__))


def nii(name, dims=(4, 3, 2), datatype=4, bitpix=16, pixdim=(1, 1, 1, 1)):
    hdr = bytearray(352)
    struct.pack_into("<i", hdr, 0, 348)
    struct.pack_into("<8h", hdr, 40, len(dims), *dims, *([1] * (7 - len(dims))))
    struct.pack_into("<hh", hdr, 70, datatype, bitpix)
    struct.pack_into("<8f", hdr, 76, *pixdim, *([1] * (8 - len(pixdim))))
    struct.pack_into("<f", hdr, 108, 352)
    hdr[344:348] = b"n+1\0"
    with open(os.path.join(here, name), "wb") as f:
        f.write(bytes(hdr) + bytes(48))


nii("datatype-1234.nii", datatype=1234)
nii("nan-spacing.nii", pixdim=(1, float("nan"), 1, 1))
nii("huge-sizes.nii", dims=(30000, 30000, 30000))
