"""vtkTetRayCastMapper says, once, that it ignores gradient opacity; volume shading it follows.

VTK's own unstructured-grid mappers drop gradient opacity silently; a warning must name it, once,
however many frames are drawn. Shading (ShadeOn) is drawn, without a warning. An
unchanged default (gradient opacity 1 everywhere) is no news. An empty input (a threshold that
keeps nothing) draws nothing without an error each frame; an error that stops every frame is said
once while it repeats; camera settings the rays ignore (a user transform) are named once. Needs a
display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, messages, offscreen_scene, require_display

require_display()

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkUnstructuredGrid

import adaptivert

box = box_tets(points=4, origin=(0, 0, 0), spacing=1.0)
prop = constant_property((1, 1, 1), 0.3)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box)
warnings = messages(mapper, vtkCommand.WarningEvent, vtkCommand.ErrorEvent)
volume, ren, win = offscreen_scene(mapper, prop, 32, 32)
ren.ResetCamera()


def frames(n=2):
    for _ in range(n):
        win.Render()
    return list(warnings)


assert frames() == [], warnings
prop.GetGradientOpacity()  # creates VTK's default (1 everywhere): nothing changes
prop.SetGradientOpacity(prop.GetGradientOpacity())
assert frames() == [], warnings
prop.ShadeOn()
assert frames(3) == [], warnings
prop.ShadeOff()
ramp = vtkPiecewiseFunction()
ramp.AddPoint(0, 0.0)
ramp.AddPoint(10, 1.0)
prop.SetGradientOpacity(ramp)
got = frames(3)
print(got)
assert len(got) == 1 and "gradient opacity" in got[0], got

# IndependentComponents off (colour straight from an RGBA array's components, as VTK's image
# mappers draw it) is named once when a multi-component array is drawn: the mapper draws its
# magnitude through the functions instead, a different image, without a word before.
from vtkmodules.util.numpy_support import numpy_to_vtk
import numpy as np
rgba = numpy_to_vtk(np.tile([1.0, 0.0, 0.0, 1.0], (box.GetNumberOfPoints(), 1)), deep=1)
rgba.SetName("rgba")
box.GetPointData().AddArray(rgba)
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectScalarArray("rgba")
mapper.SetVectorMode(adaptivert.vtkTetRayCastMapper.MAGNITUDE)
assert frames(2)[1:] == [], warnings[1:]  # independent components (VTK's default): no news
prop.IndependentComponentsOff()
got = frames(3)
print(got[1:])
assert len(got) == 2 and "IndependentComponents off" in got[1] and "4 components" in got[1], got
prop.IndependentComponentsOn()
mapper.SetScalarModeToDefault()
mapper.SetVectorMode(adaptivert.vtkTetRayCastMapper.DISABLED)

empty = vtkUnstructuredGrid()
empty.SetPoints(box.GetPoints())
mapper.SetInputData(empty)
got = frames(2)
assert len(got) == 2, got  # no error for the empty grid

# An error that stops every frame alike (an array name that is not there) is said once while it
# repeats, however often ParaView renders; once a frame draws again, it may be said anew.
mapper.SetInputData(box)
mapper.SetScalarModeToUsePointFieldData()
mapper.SelectScalarArray("no such array")
got = frames(4)
print(got[2:])
assert len(got) == 3 and "no such array" in got[2], got
mapper.SetScalarModeToDefault()
assert frames(1)[3:] == [], warnings[3:]
mapper.SetScalarModeToUsePointFieldData()
assert len(frames(2)) == 4, warnings  # said again after the good frame, once
mapper.SetScalarModeToDefault()

# Camera settings the rays do not follow are named once (opaque geometry follows them).
cam = ren.GetActiveCamera()
from vtkmodules.vtkCommonTransforms import vtkTransform
stretch = vtkTransform()
stretch.Scale(1.2, 1.0, 1.0)
cam.SetUserTransform(stretch)
got = frames(3)
print(got[4:])
assert len(got) == 5 and "user transform" in got[4], got
cam.SetUserTransform(None)
print("ok")
