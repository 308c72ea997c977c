"""vtkTetRayCastMapper draws a volume property function emptied of its points (RemoveAllPoints) as 0
everywhere, as VTK evaluates it and VTK's mappers draw it.

An emptied scalar-opacity function drew the volume opaque (the box went from 0.75 to full opacity
instead of vanishing), and an emptied colour function drew it white instead of black. Needs a
display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, offscreen_scene, require_display

require_display()

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction

import adaptivert

mapper = adaptivert.vtkTetRayCastMapper()
mapper.AutoAdjustSampleDistancesOff()
mapper.SetInputData(box_tets())
prop = constant_property((1.0, 0.5, 0.2), 0.5)
volume, ren, win = offscreen_scene(mapper, prop, 80, 60)
look_down_z(ren, 1.5)


def centre():
    win.Render()
    return grab(win)[25:35, 35:45].reshape(-1, 3).mean(axis=0)


before = centre()
print("as set:", before)
assert abs(before[0] - 0.75 * 255) < 3, before  # two units of opacity 0.5 per unit

prop.GetRGBTransferFunction().RemoveAllPoints()
black = centre()
print("colour function emptied:", black)
assert black.max() < 3, black

prop.GetRGBTransferFunction().AddRGBPoint(1, 1.0, 0.5, 0.2)
prop.GetScalarOpacity().RemoveAllPoints()
hidden = centre()
print("opacity function emptied:", hidden)
assert hidden.max() < 3, hidden

opacity = vtkPiecewiseFunction()
opacity.AddPoint(1, 0.5)
prop.SetScalarOpacity(opacity)
again = centre()
print("opacity function set again:", again)
assert abs(again[0] - before[0]) < 3, (again, before)
