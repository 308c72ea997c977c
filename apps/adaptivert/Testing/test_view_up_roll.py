"""render --roll and --view-up turn the picture as a camera does: on a square image, --roll 90 is
the plain render turned a quarter (the same rays, up to rounding), and --view-up 0,0,-1 (the
default's up reversed) is the plain render turned half round. Each is checked against the plain
render rotated in numpy, and against the plain render itself (they must differ)."""
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

ART = os.path.join(os.environ["ART_BIN"], "adaptivert")
OUT = os.path.join(os.environ["ART_TEST_OUTPUT"], "view-up-roll")
DATA = os.path.join(os.environ["ART_SOURCE_DIR"], "data", "ct-head-128.mha")
os.makedirs(OUT, exist_ok=True)


def render(name, *extra):
    path = os.path.join(OUT, name + ".png")
    subprocess.run([ART, "render", DATA, "-o", path, "--size", "64x64", "--tets", "2000", "--no-relocate",
                    "--no-error", "-q", *extra], check=True, stdout=subprocess.DEVNULL)
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[::-1, :, :3]  # top row first
    return a.astype(np.float64) / 255.0


def psnr(a, b):
    rmse = np.sqrt(np.mean((a - b) ** 2))
    return float("inf") if rmse == 0 else -20 * np.log10(rmse)


# Roll comes after --elevation, so the raised view turns whole; the view-up is taken before it,
# so the up-down pair is compared level (raised, each would look from its own side).
raised = render("raised", "--elevation", "20")
rolled = render("raised-roll90", "--elevation", "20", "--roll", "90")
level = render("level")
flipped = render("level-up-down", "--view-up", "0,0,-1")
# VTK's Roll(90) turns the view up clockwise about the view direction, so the picture turns a
# quarter counter-clockwise (numpy's rot90 with k=1).
checks = [("--roll 90", rolled, raised, np.rot90(raised, k=1)),
          ("--view-up 0,0,-1", flipped, level, np.rot90(level, k=2))]
failed = False
for name, got, plain, expected in checks:
    same, unturned = psnr(got, expected), psnr(got, plain)
    print(f"{name}: {same:.1f} dB against the plain render turned, {unturned:.1f} dB against it unturned")
    if not (same >= 40 and unturned < 30):
        failed = True
sys.exit(1 if failed else 0)
