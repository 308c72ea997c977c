#!/usr/bin/python3
"""Writes the synthetic volumes behind the default-transfer-function tests (tests/data/synthetic):
  heart-like.vti  an MRI-like 8-bit volume: noisy background near 0, a myocardium shell at ~110,
                  bright blood pools at ~200 inside it, a few hot outlier voxels at 255
  brain-like.vti  a skull-stripped-MRI-like 16-bit volume: background exactly 0, an ellipsoid of
                  grey matter ~400 with folded white matter ~700 inside
  labels.vti      a label map: 0 background, 1 a slab, 2 a ball, 3 a rod
Deterministic (seeded); run again to re-make them: /usr/bin/python3 tests/data/make_synthetic_volumes.py"""
import os

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter

N = 48
here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "synthetic")


def grid():
    c = (np.arange(N) - (N - 1) / 2.0) / (N / 2.0)
    return np.meshgrid(c, c, c, indexing="ij")  # x, y, z in [-1, 1]


def write(name, values, vtk_type_array):
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    image.SetSpacing(1.5, 1.5, 1.5)
    a = numpy_support.numpy_to_vtk(values.transpose(2, 1, 0).ravel(), deep=1, array_type=vtk_type_array)
    a.SetName("scalars")
    image.GetPointData().SetScalars(a)
    w = vtkXMLImageDataWriter()
    w.SetFileName(os.path.join(here, name))
    w.SetInputData(image)
    w.SetCompressorTypeToZLib()
    w.Write()


def heart(rng):
    x, y, z = grid()
    v = rng.uniform(0, 6, x.shape)  # background noise
    r = np.sqrt((x / 0.6) ** 2 + (y / 0.5) ** 2 + (z / 0.75) ** 2)
    v[r < 1.0] = 110 + rng.normal(0, 8, x.shape)[r < 1.0]
    pool = np.sqrt(((x - 0.15) / 0.3) ** 2 + (y / 0.28) ** 2 + (z / 0.5) ** 2) < 1.0
    pool |= np.sqrt(((x + 0.25) / 0.22) ** 2 + ((y + 0.05) / 0.22) ** 2 + ((z - 0.1) / 0.4) ** 2) < 1.0
    v[pool] = 200 + rng.normal(0, 8, x.shape)[pool]
    hot = rng.integers(0, N, (20, 3))
    v[hot[:, 0], hot[:, 1], hot[:, 2]] = 255
    return np.clip(np.round(v), 0, 255).astype(np.uint8)


def brain(rng):
    x, y, z = grid()
    v = np.zeros(x.shape)
    r = np.sqrt((x / 0.7) ** 2 + (y / 0.85) ** 2 + (z / 0.6) ** 2)
    inside = r < 1.0
    v[inside] = 400 + rng.normal(0, 20, x.shape)[inside]
    folds = inside & (r < 0.8) & (np.sin(9 * x) * np.sin(7 * y) + np.sin(8 * z) > 0.2)
    v[folds] = 700 + rng.normal(0, 20, x.shape)[folds]
    return np.round(v).astype(np.int16)


def labels():
    x, y, z = grid()
    v = np.zeros(x.shape, dtype=np.uint8)
    v[(np.abs(z + 0.5) < 0.15) & (np.abs(x) < 0.8) & (np.abs(y) < 0.8)] = 1
    v[np.sqrt(x ** 2 + y ** 2 + (z - 0.2) ** 2) < 0.45] = 2
    v[(np.sqrt((x - 0.6) ** 2 + (y + 0.6) ** 2) < 0.12) & (np.abs(z) < 0.8)] = 3
    return v


if __name__ == "__main__":
    from vtkmodules.util.vtkConstants import VTK_SHORT, VTK_UNSIGNED_CHAR
    os.makedirs(here, exist_ok=True)
    rng = np.random.default_rng(24)
    write("heart-like.vti", heart(rng), VTK_UNSIGNED_CHAR)
    write("brain-like.vti", brain(rng), VTK_SHORT)
    write("labels.vti", labels(), VTK_UNSIGNED_CHAR)
