"""Shared functions of the plugin's pvbatch tests: the camera `adaptivert render` frames its data with,
the transfer function of a 'scalar r g b opacity' file, one still screenshot, and where things are."""
import json
import math
import os
import subprocess

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetOpacityTransferFunction, Render, SaveScreenshot, Show)

SOURCE = os.environ.get("ART_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
OUTPUT = os.environ.get("ART_TEST_OUTPUT", ".")
ADAPTIVERT = os.path.join(os.environ.get("ART_BIN", os.path.join(SOURCE, "build", "bin")), "adaptivert")
DEFAULT_CT = os.path.join(SOURCE, "data", "ct-head-128.mha")
TF_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ct-skin-bone.tf")


def ranks():
    return servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def read_tf(path=TF_FILE):
    """(unit distance, [(scalar, r, g, b, opacity)]) of a transfer-function file."""
    unit, nodes = 1.0, []
    for line in open(path):
        words = line.split("#")[0].split()
        if not words:
            continue
        if words[0] == "unit-distance":
            unit = float(words[1])
        else:
            nodes.append(tuple(float(w) for w in words))
    return unit, nodes


def opacity_function(array, path=TF_FILE):
    """ParaView's scalar-opacity function of `array`, set to the file's opacities."""
    _, nodes = read_tf(path)
    pwf = GetOpacityTransferFunction(array)
    pwf.Points = [v for n in nodes for v in (n[0], n[4], 0.5, 0.0)]
    return pwf


def show_tets(source, array, size=(400, 400), path=TF_FILE, **settings):
    """Shows `source` as 'Tet Ray Cast Volume' with the file's transfer function, in a view
    with a black background and nothing else."""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    if "UseColorPaletteForBackground" in view.ListProperties():
        view.UseColorPaletteForBackground = 0
    view.Background = [0, 0, 0]
    display = Show(source, view)
    display.Representation = "Tet Ray Cast Volume"
    ColorBy(display, ("POINTS", array))
    unit, nodes = read_tf(path)
    lut = GetColorTransferFunction(array)
    lut.ColorSpace = "RGB"
    lut.RGBPoints = [v for n in nodes for v in n[:4]]
    opacity_function(array, path)
    display.ScalarOpacityUnitDistance = unit
    display.AutoAdjustSampleDistances = 0
    # The caster's defaults, then the settings asked for (a display shown again keeps its own).
    chosen = dict(Integrator="Exact", IsoValues=[], IsoOpacity=1.0, EarlyRayTermination=0.99)
    chosen.update(settings)
    for k, v in chosen.items():
        setattr(display, k, v)
    return view, display


def camera_of_render(view, camera):
    """The camera `adaptivert render --json` reported (its "camera" object) on `view`. A view's
    first Render resets its camera to the data, so that happens first."""
    Render(view)
    view.CameraPosition = camera["position"]
    view.CameraFocalPoint = camera["focal_point"]
    view.CameraViewUp = camera["view_up"]
    view.CameraViewAngle = camera["view_angle"]
    view.CameraParallelProjection = 1 if camera["parallel"] else 0
    view.CameraParallelScale = camera["parallel_scale"]


def render_json(*args):
    """`adaptivert render ARGS --json`'s report (its camera among it)."""
    return json.loads(adaptivert("render", *args, "--json"))


def frame_like_render(view, bounds, size, azimuth=0.0, elevation=0.0):
    """A camera for comparing pvbatch images with each other: looking along +y with z up at the
    bounds' centre, from where the bounding sphere fills the view angle (art::Camera::Frame)."""
    centre = [0.5 * (bounds[2 * a] + bounds[2 * a + 1]) for a in range(3)]
    radius = 0.5 * math.sqrt(sum((bounds[2 * a + 1] - bounds[2 * a]) ** 2 for a in range(3)))
    aspect = size[0] / size[1]
    half = math.radians(view.CameraViewAngle) / 2
    narrow = math.atan(math.tan(half) * aspect) if aspect < 1 else half
    dist = radius / math.sin(narrow)
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1] - dist, centre[2]]
    view.CameraViewUp = [0, 0, 1]
    view.CameraParallelProjection = 0
    camera = view.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()


def screenshot(view, path, size):
    Render(view)
    SaveScreenshot(path, view, ImageResolution=list(size))
    return path


def compare(a, b, min_psnr):
    """`adaptivert compare`'s figures of two images (exit 1 below min_psnr)."""
    run = subprocess.run([ADAPTIVERT, "compare", "--json", "--quiet", a, b, "--min-psnr", str(min_psnr)],
                         capture_output=True, text=True)
    figures = json.loads(run.stdout) if run.stdout.strip() else {}
    return run.returncode, figures


def adaptivert(*args):
    run = subprocess.run([ADAPTIVERT, *args], capture_output=True, text=True)
    if run.returncode != 0:
        raise SystemExit("adaptivert %s failed: %s" % (" ".join(args), run.stderr.strip()))
    return run.stdout


def vtk_window_render(mesh, out, view, size, tf=TF_FILE, options=()):
    """The same mesh, camera and transfer function drawn by vtkTetRayCastMapper in a window of the
    project's own VTK build (vtk_window_render.py under Debian's Python, outside ParaView's), with
    render's options --integrator, --iso, --iso-opacity and --ert."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PV_PLUGIN_PATH")}
    env["PYTHONPATH"] = os.environ["ART_PYTHONPATH"]
    here = os.path.dirname(os.path.abspath(__file__))
    camera = [*view.CameraPosition, *view.CameraFocalPoint, *view.CameraViewUp, view.CameraViewAngle]
    subprocess.run(["/usr/bin/python3", os.path.join(here, "vtk_window_render.py"), mesh, tf, out,
                    str(size[0]), str(size[1]), *(repr(float(v)) for v in camera), *options], env=env, check=True)
    return out
