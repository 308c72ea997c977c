"""The set-up the vtkTetRayCastMapper Python tests share: a display check, a tetrahedralised box of
constant value, a constant-colour volume property, an offscreen window around a mapper, and the
window's pixels as a numpy array, and the messages a mapper sends. Each test imports it from its own folder (the script's folder is
first on sys.path) and keeps its checks to itself.
"""
import os
import sys


def require_display():
    """Exits with 77 (ctest's SKIP_RETURN_CODE for these tests) when there is no display. Call it
    before anything else: VTK is imported only after it (below), so a machine without a display
    skips whatever its VTK is."""
    if not os.environ.get("DISPLAY"):
        print("no DISPLAY: skipped (run under xvfb-run -a)")
        sys.exit(77)


require_display()

from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,  # noqa: E402
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401  (the OpenGL window behind vtkRenderWindow)


def box_tets(points=5, origin=(-1, -1, -1), spacing=0.5, value=1.0):
    """A box of points^3 float points, all equal to value, split into tetrahedra by
    vtkDataSetTriangleFilter. The default is the 2 x 2 x 2 box centred on the origin."""
    image = vtkImageData()
    image.SetDimensions(points, points, points)
    image.SetOrigin(*origin)
    image.SetSpacing(spacing, spacing, spacing)
    image.AllocateScalars(10, 1)  # VTK_FLOAT
    image.GetPointData().GetScalars().Fill(value)
    tri = vtkDataSetTriangleFilter()
    tri.SetInputData(image)
    tri.Update()
    return tri.GetOutput()


def constant_property(colour, opacity, unit=1.0):
    """A vtkVolumeProperty of one colour and one opacity over the scalars 0 .. 2 (the box's value 1
    in the middle); opacity is reached through unit world units of thickness."""
    ctf = vtkColorTransferFunction()
    ctf.AddRGBPoint(0, *colour)
    ctf.AddRGBPoint(2, *colour)
    otf = vtkPiecewiseFunction()
    otf.AddPoint(0, opacity)
    otf.AddPoint(2, opacity)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit)
    return prop


def offscreen_scene(mapper, prop, width, height):
    """A vtkVolume of mapper and prop in a renderer with a black background, in an offscreen
    window of width x height pixels. Returns (volume, renderer, window); nothing is rendered yet."""
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(width, height)
    win.AddRenderer(ren)
    return volume, ren, win


def look_down_z(ren, parallel_scale):
    """A parallel camera on the +z axis looking at the origin, y up, showing 2 * parallel_scale
    world units top to bottom."""
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetPosition(0, 0, 10)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 1, 0)
    cam.SetParallelScale(parallel_scale)
    ren.ResetCameraClippingRange()
    return cam


def grab(win):
    """The window's last rendered back buffer as a (height, width, 3) uint8 array, row 0 at the
    bottom (render first)."""
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(win)
    grabber.SetInputBufferTypeToRGB()
    grabber.ReadFrontBufferOff()
    grabber.Update()
    out = grabber.GetOutput()
    width, height = out.GetDimensions()[:2]
    return vtk_to_numpy(out.GetPointData().GetScalars()).reshape(height, width, 3)


def messages(mapper, *events):
    """A list that collects the text of every one of `events` (default: vtkCommand.ErrorEvent)
    the mapper fires, in order."""
    texts = []

    @calldata_type(VTK_STRING)
    def collect(obj, event, text):
        texts.append(text)

    for event in events or (vtkCommand.ErrorEvent,):
        mapper.AddObserver(event, collect)
    return texts
