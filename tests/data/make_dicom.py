#!/usr/bin/python3
"""Makes tests/data/dicom/: a 4-slice, 16 x 12 CT series cut from data/ct-head-128.mha
(x 56..71, y 60..71, z 26..29), int16 HU stored directly (slope 1, intercept 0), so the
DICOM reader test has a known answer. Run once; the output is committed."""
import datetime
import os

import numpy as np
import pydicom
from pydicom.dataset import FileDataset, FileMetaDataset
from pydicom.uid import ExplicitVRLittleEndian, generate_uid
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkMetaImageReader

here = os.path.dirname(os.path.abspath(__file__))
r = vtkMetaImageReader()
r.SetFileName(os.path.join(here, "..", "..", "data", "ct-head-128.mha"))
r.Update()
img = r.GetOutput()
nx, ny, nz = img.GetDimensions()
vol = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(nz, ny, nx)
crop = vol[26:30, 60:72, 56:72].astype(np.int16)  # z, y, x
sp = img.GetSpacing()
study, series = generate_uid(), generate_uid()
out = os.path.join(here, "dicom")
os.makedirs(out, exist_ok=True)
for k in range(crop.shape[0]):
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = "1.2.840.10008.5.1.4.1.1.2"  # CT Image Storage
    meta.MediaStorageSOPInstanceUID = generate_uid()
    meta.TransferSyntaxUID = ExplicitVRLittleEndian
    ds = FileDataset(None, {}, file_meta=meta, preamble=b"\0" * 128)
    ds.SOPClassUID = meta.MediaStorageSOPClassUID
    ds.SOPInstanceUID = meta.MediaStorageSOPInstanceUID
    ds.StudyInstanceUID, ds.SeriesInstanceUID = study, series
    ds.Modality = "CT"
    ds.PatientName = "Test^Crop"
    ds.StudyDate = datetime.date(2026, 1, 1).strftime("%Y%m%d")
    ds.InstanceNumber = k + 1
    ds.ImagePositionPatient = [0.0, 0.0, float(k * sp[2])]
    ds.ImageOrientationPatient = [1, 0, 0, 0, 1, 0]
    ds.PixelSpacing = [sp[1], sp[0]]
    ds.SliceThickness = sp[2]
    ds.Rows, ds.Columns = crop.shape[1], crop.shape[2]
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated = ds.BitsStored = 16
    ds.HighBit = 15
    ds.PixelRepresentation = 1
    ds.RescaleSlope, ds.RescaleIntercept = 1, 0
    ds.PixelData = crop[k].tobytes()
    ds.is_little_endian, ds.is_implicit_VR = True, False
    ds.save_as(os.path.join(out, "slice_%03d.dcm" % k), write_like_original=False)
print("crop sum", int(crop.astype(np.int64).sum()), "first", int(crop[0, 0, 0]), "min", crop.min(), "max", crop.max())
