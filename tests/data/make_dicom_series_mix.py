#!/usr/bin/python3
"""Makes two DICOM folders that vtkDICOMImageReader (VTK 9.1) misreads, as PACS exports are:
dicom-scout/: a 3-slice, 3-row, 4-column CT series (voxel (i, j, k) = 100 k + 10 j + i) beside a
2-image 5 x 5 scout series (value 7000) whose SeriesInstanceUID sorts first: VTK read the scout's
series with the CT's size (heap corruption, abort). dicom-mixed-size/: the CT series with its
middle slice 2 x 2 (read as garbage). dicom-compressed/: JPEG Lossless transfer syntax (VTK cannot
decode it; its error named neither that nor a way out). dicom-gap/: 4 slices at 30, 31.5, 33 and
36 mm (one missing): VTK stacked them 1.5 mm apart without a word. dicom-multiframe/: one image of
3 frames (NumberOfFrames 3): VTK read its first frame as the whole volume. Run once; the output is committed."""
import os
import shutil

import numpy as np
import pydicom
from pydicom.dataset import FileDataset, FileMetaDataset
from pydicom.encaps import encapsulate
from pydicom.uid import ExplicitVRLittleEndian

here = os.path.dirname(os.path.abspath(__file__))
STUDY = "1.2.826.0.1.3680043.8.498.1"


def write(path, series, number, position, rows, cols, pixels, iop=(1, 0, 0, 0, 1, 0), syntax=ExplicitVRLittleEndian):
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = "1.2.840.10008.5.1.4.1.1.2"  # CT Image Storage
    meta.MediaStorageSOPInstanceUID = series + "." + str(number)
    meta.TransferSyntaxUID = syntax
    ds = FileDataset(None, {}, file_meta=meta, preamble=b"\0" * 128)
    ds.SOPClassUID = meta.MediaStorageSOPClassUID
    ds.SOPInstanceUID = meta.MediaStorageSOPInstanceUID
    ds.StudyInstanceUID, ds.SeriesInstanceUID = STUDY, series
    ds.Modality = "CT"
    ds.PatientName = "Test^Series"
    ds.StudyDate = "20260101"
    ds.InstanceNumber = number
    ds.ImagePositionPatient = [float(x) for x in position]
    ds.ImageOrientationPatient = [float(x) for x in iop]
    ds.PixelSpacing = [1.0, 1.0]
    ds.SliceThickness = 1.5
    ds.Rows, ds.Columns = rows, cols
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated, ds.BitsStored, ds.HighBit, ds.PixelRepresentation = 16, 16, 15, 1
    ds.RescaleSlope, ds.RescaleIntercept = 1, 0
    ds.PixelData = np.asarray(pixels, dtype="<i2").tobytes()
    if syntax != ExplicitVRLittleEndian:  # a JPEG frame's start, enough for the header to say so
        ds.PixelData = encapsulate([b"\xff\xd8\xff\xc3" + bytes(60)])
        ds["PixelData"].is_undefined_length = True
    ds.is_little_endian, ds.is_implicit_VR = True, False
    ds.save_as(path, write_like_original=False)


def ct(folder, odd=None):
    for k in range(3):
        rows, cols = (2, 2) if k == odd else (3, 4)
        pixels = np.fromfunction(lambda j, i: 100 * k + 10 * j + i, (rows, cols))
        write(os.path.join(folder, "ct%d.dcm" % k), STUDY + ".3", k + 1, (10, 20, 30 + 1.5 * k), rows, cols, pixels)


for name in ("dicom-scout", "dicom-mixed-size", "dicom-compressed", "dicom-gap", "dicom-multiframe"):
    shutil.rmtree(os.path.join(here, name), ignore_errors=True)
    os.makedirs(os.path.join(here, name))
ct(os.path.join(here, "dicom-scout"))
for n in range(2):  # series UID ".2" sorts before the CT's ".3"
    write(os.path.join(here, "dicom-scout", "scout%d.dcm" % n), STUDY + ".2", n + 1, (0, 30 + n, 0), 5, 5,
          np.full((5, 5), 7000), iop=(1, 0, 0, 0, 0, -1))
ct(os.path.join(here, "dicom-mixed-size"), odd=1)
for k in range(2):
    write(os.path.join(here, "dicom-compressed", "jpeg%d.dcm" % k), STUDY + ".4", k + 1, (0, 0, 1.5 * k), 8, 8,
          np.zeros((8, 8)), syntax="1.2.840.10008.1.2.4.70")
for n, z in enumerate((30, 31.5, 33, 36)):
    write(os.path.join(here, "dicom-gap", "ct%d.dcm" % n), STUDY + ".5", n + 1, (10, 20, z), 3, 4,
          np.full((3, 4), 10 * n))
frames = os.path.join(here, "dicom-multiframe", "frames.dcm")
write(frames, STUDY + ".6", 1, (10, 20, 30), 3, 4, np.zeros((3, 4)))
ds = pydicom.dcmread(frames)
ds.NumberOfFrames = 3
ds.PixelData = np.arange(36, dtype="<i2").tobytes()
ds.save_as(frames)
