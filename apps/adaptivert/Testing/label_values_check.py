"""`reduce --labels --values` then `render`: the values inside each label, in its hue, brightening
with the values as the default function says, against the closed form.

tests/data/meshing/halves-24.mha holds label 1 (x in 4 .. 11) beside label 2 (x in 12 .. 19), y and
z in 4 .. 19; halves-24-ramp.mha the values 10 z. Seen along y under parallel projection each ray
holds one value, so a pixel is c(label) * luminance(v) * (1 - exp(-tau(v) d)) over black: c the
label's categorical colour, luminance 0.3 .. 1 and tau from LabelOpacity / 5 to LabelOpacity per
unit distance (the voxel spacing, 1) over the values' window the mesh records, d the slab's depth
(16, the meshed labels' surfaces at half a voxel outside the centres). `--label-colours flat`
gives each label one colour at every height; the values' own brightness is then gone. `--tf`
sets the brightness over the values, still in each label's hue.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

ART = os.path.join(os.environ["ART_BIN"], "adaptivert")
DATA = os.path.join(os.environ["ART_SOURCE_DIR"], "tests", "data", "meshing")
OUT = os.path.join(os.environ["ART_TEST_OUTPUT"], "label-values")
os.makedirs(OUT, exist_ok=True)
PALETTE = {1: np.array([1.000, 0.498, 0.055]), 2: np.array([0.173, 0.627, 0.173])}
LABEL_OPACITY = 0.5
W = H = 160


def run(*args):
    r = subprocess.run([ART, *args], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"adaptivert {' '.join(args)} failed ({r.returncode}): {r.stderr}")
    return r.stdout


mesh = os.path.join(OUT, "halves.vtu")
run("reduce", os.path.join(DATA, "halves-24.mha"), mesh, "--labels", "--values", os.path.join(DATA, "halves-24-ramp.mha"),
    "--tets", "2000", "--quiet")
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(mesh)
reader.Update()
window = vtk_to_numpy(reader.GetOutput().GetFieldData().GetArray("source_window"))[0]
print(f"values' window recorded by the mesh: {window[0]:.3f} .. {window[1]:.3f}")


def render(name, *extra):
    png = os.path.join(OUT, name + ".png")
    info = json.loads(run("render", mesh, "-o", png, "--size", f"{W}x{H}", "--parallel", "--no-error", "--json", "-q",
                          *extra))
    cam = info["camera"]
    assert abs(cam["view_up"][2] - 1) < 1e-9 and cam["position"][1] < cam["focal_point"][1], cam  # along +y, z up
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars()).reshape(H, W, -1)[::-1, :, :3] / 255.0
    s, f = cam["parallel_scale"], cam["focal_point"]
    z = f[2] + s * (1 - 2 * (np.arange(H) + 0.5) / H)  # row 0 at the top
    x = f[0] + s * (2 * (np.arange(W) + 0.5) / W - 1)
    return img, x, z


def expected(label, v):
    t = np.clip((v - window[0]) / (window[1] - window[0]), 0, 1)
    tau0, tau1 = -math.log(1 - 0.2 * LABEL_OPACITY), -math.log(1 - LABEL_OPACITY)
    alpha = 1 - np.exp(-(tau0 + t * (tau1 - tau0)) * 16.0)
    return PALETTE[label][None, :] * ((0.3 + 0.7 * t) * alpha)[:, None]


def inside(label, x):
    return (x > 5.5) & (x < 9.5) if label == 1 else (x > 13.5) & (x < 17.5)


img, x, z = render("values")
rows = (z > 5.5) & (z < 17.5)
worst = 0.0
for label in (1, 2):
    cols = inside(label, x)
    got = img[rows][:, cols].mean(1)  # one value per row
    want = expected(label, 10 * z[rows])
    err = np.abs(got - want).max()
    # The hue: each row's colour is the label's colour times one brightness.
    k = got @ PALETTE[label] / (PALETTE[label] @ PALETTE[label])
    hue = np.abs(got - k[:, None] * PALETTE[label][None, :]).max()
    print(f"label {label}: brightness {k.min():.3f} .. {k.max():.3f} over z {z[rows].min():.1f} .. {z[rows].max():.1f}; "
          f"max |pixel - closed form| {err:.4f}, off its hue by {hue:.4f}")
    assert np.all(np.diff(k[::-1]) > -2e-3), f"label {label}: brightness does not rise with z: {k[::-1]}"  # 8 bits
    assert k.max() > 1.6 * k.min(), (label, k.min(), k.max())
    assert hue < 0.02, (label, hue)
    worst = max(worst, err)
assert worst < 0.03, worst

flat, x, z = render("flat", "--label-colours", "flat")
for label in (1, 2):
    got = flat[rows][:, inside(label, x)].mean(1)
    spread = got.max(0) - got.min(0)
    print(f"flat label {label}: colour {got.mean(0).round(3)}, spread over z {spread.max():.4f}")
    assert spread.max() < 0.02 and np.abs(got.mean(0) - PALETTE[label]).max() < 0.02, (label, got.mean(0), spread)
# A --tf preset sets the brightness over the values instead, still in each label's hue: grey-ramp
# (black to white over the values' range, opacity 0 to 0.2) brightens with z too.
tinted, x, z = render("grey-ramp", "--tf", "grey-ramp")
for label in (1, 2):
    got = tinted[rows][:, inside(label, x)].mean(1)
    k = got @ PALETTE[label] / (PALETTE[label] @ PALETTE[label])
    hue = np.abs(got - k[:, None] * PALETTE[label][None, :]).max()
    print(f"--tf grey-ramp label {label}: brightness {k.min():.3f} .. {k.max():.3f}, off its hue by {hue:.4f}")
    assert hue < 0.02 and k[0] > 2 * k[-1], (label, hue, k[0], k[-1])  # row 0 is the top, the highest z
print("ok")
