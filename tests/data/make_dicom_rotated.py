#!/usr/bin/python3
"""Makes tests/data/dicom-rotated/: a 3-slice, 3-row, 4-column series whose rows run along +y and
columns along -x (ImageOrientationPatient 0,1,0,-1,0,0), non-square pixels (row spacing 0.9,
column spacing 0.7), slices 1.5 apart from (10, 20, 30), files and instance numbers in reverse
order. Voxel (column i, row j, slice k) holds 100 k + 10 j + i, so a test can check where each
voxel lands. Run once; the output is committed."""
import os

import numpy as np
import pydicom
from pydicom.dataset import FileDataset, FileMetaDataset
from pydicom.uid import ExplicitVRLittleEndian, generate_uid

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "dicom-rotated")
os.makedirs(out, exist_ok=True)
K, R, C = 3, 3, 4
vol = np.fromfunction(lambda k, j, i: 100 * k + 10 * j + i, (K, R, C)).astype(np.int16)
r, c = np.array([0.0, 1.0, 0.0]), np.array([-1.0, 0.0, 0.0])
n = np.cross(r, c)
study, series = generate_uid(), generate_uid()
for k in range(K):
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = "1.2.840.10008.5.1.4.1.1.2"  # CT Image Storage
    meta.MediaStorageSOPInstanceUID = generate_uid()
    meta.TransferSyntaxUID = ExplicitVRLittleEndian
    ds = FileDataset(None, {}, file_meta=meta, preamble=b"\0" * 128)
    ds.SOPClassUID = meta.MediaStorageSOPClassUID
    ds.SOPInstanceUID = meta.MediaStorageSOPInstanceUID
    ds.StudyInstanceUID, ds.SeriesInstanceUID = study, series
    ds.Modality = "CT"
    ds.PatientName = "Test^Rotated"
    ds.StudyDate = "20260101"
    ds.InstanceNumber = K - k
    ds.ImagePositionPatient = [float(x) for x in np.array([10.0, 20.0, 30.0]) + k * 1.5 * n]
    ds.ImageOrientationPatient = [float(x) for x in np.concatenate([r, c])]
    ds.PixelSpacing = [0.9, 0.7]  # between rows, between columns
    ds.SliceThickness = 1.5
    ds.Rows, ds.Columns = R, C
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated = ds.BitsStored = 16
    ds.HighBit = 15
    ds.PixelRepresentation = 1
    ds.RescaleSlope, ds.RescaleIntercept = 1, 0
    ds.PixelData = vol[k].tobytes()
    ds.is_little_endian, ds.is_implicit_VR = True, False
    ds.save_as(os.path.join(out, "im%03d.dcm" % (K - 1 - k)), write_like_original=False)
