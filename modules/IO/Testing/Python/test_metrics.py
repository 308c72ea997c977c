"""adaptivert imports from Debian's python3 and its vtkImageMetrics gives known answers."""
import math
import os
import sys

import adaptivert
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkCommonCore import vtkFloatArray


def constant_image(value, w=16, h=8, alpha=1.0):
    img = vtkImageData()
    img.SetDimensions(w, h, 1)
    a = vtkFloatArray()
    a.SetNumberOfComponents(4)
    a.SetNumberOfTuples(w * h)
    for i in range(w * h):
        a.SetTuple4(i, value, value, value, alpha)
    img.GetPointData().SetScalars(a)
    return img


m = adaptivert.vtkImageMetrics()
assert math.isnan(m.GetRMSE()) and math.isnan(m.GetSSIM()), (m.GetRMSE(), m.GetSSIM())  # nothing compared yet
assert m.Compare(constant_image(0.25), constant_image(0.35)), m.GetErrorMessage()
# Both opaque: alpha is left out, RGB differs by 0.1 (RMSE 0.1, PSNR 20 dB).
assert abs(m.GetRMSE() - 0.1) < 1e-6, m.GetRMSE()
assert abs(m.GetPSNR() - 20.0) < 1e-4, m.GetPSNR()
# Translucent (alpha 0.5 in both): three of four channels differ by 0.1, RMSE = sqrt(3/4) * 0.1.
assert m.Compare(constant_image(0.25, alpha=0.5), constant_image(0.35, alpha=0.5)), m.GetErrorMessage()
expected = math.sqrt(0.75) * 0.1
assert abs(m.GetRMSE() - expected) < 1e-6, m.GetRMSE()
assert abs(m.GetPSNR() - (-20 * math.log10(expected))) < 1e-4, m.GetPSNR()
assert not m.Compare(constant_image(0.1, 4, 4), constant_image(0.1, 5, 4))
assert "differ in size" in m.GetErrorMessage(), m.GetErrorMessage()
# A failed comparison leaves no figures behind: the last pair's RMSE (or the defaults' 0 and SSIM 1)
# read as a pass to a script that did not test Compare's result.
assert all(math.isnan(v) for v in (m.GetRMSE(), m.GetPSNR(), m.GetSSIM(), m.GetMaxAbsDifference())), (
    m.GetRMSE(), m.GetPSNR(), m.GetSSIM(), m.GetMaxAbsDifference())
assert not m.CompareFiles("/nonexistent/a.png", "/nonexistent/b.png")
assert "/nonexistent/a.png" in m.GetErrorMessage()
# A NaN pixel (a float EXR can hold one) is an error, not PSNR "identical".
nan = constant_image(0.25)
nan.GetPointData().GetScalars().SetComponent(3, 1, float("nan"))
assert not m.Compare(nan, constant_image(0.25))
assert "NaN or infinite" in m.GetErrorMessage(), m.GetErrorMessage()
# Integer images are fractions of their type's largest value: the same picture in 8 and 16 bits
# (as vtkPNGReader gives a 16-bit PNG) is identical; 16 bits read as values up to 65535 gave -90 dB.
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray, vtkUnsignedShortArray


def ramp(array_type, scale):
    img = vtkImageData()
    img.SetDimensions(16, 16, 1)
    a = array_type()
    a.SetNumberOfTuples(256)
    for i in range(256):
        a.SetValue(i, i * scale)
    img.GetPointData().SetScalars(a)
    return img


assert m.Compare(ramp(vtkUnsignedCharArray, 1), ramp(vtkUnsignedShortArray, 257)), m.GetErrorMessage()
assert m.GetRMSE() < 1e-6 and m.GetMaxAbsDifference() < 1e-6, (m.GetRMSE(), m.GetPSNR())
print("ok", adaptivert.__version__, file=sys.stderr)
