"""vtkTetRayCastMapper says once why it refuses an input, not at every frame.

A masked field (one NaN point scalar, as a simulation or a ParaView filter leaves it) cannot be
drawn: the error names how many points and where the first one is, once over several frames
(each camera move in ParaView said it again); once the input is fixed and Modified() it draws.
Needs a display (skips with exit 77).
"""
import math

from mapper_scene import box_tets, constant_property, grab, messages, offscreen_scene, require_display

require_display()

import adaptivert

box = box_tets(points=3, origin=(0, 0, 0), spacing=1.0)
scalars = box.GetPointData().GetScalars()
for i in range(box.GetNumberOfPoints()):
    if box.GetPoint(i) == (2.0, 1.0, 0.0):
        scalars.SetValue(i, math.nan)
prop = constant_property((1, 1, 1), 0.3)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(box)
errors = messages(mapper)
volume, ren, win = offscreen_scene(mapper, prop, 32, 32)
ren.ResetCamera()
for _ in range(3):
    ren.GetActiveCamera().Azimuth(10)
    win.Render()
print(errors)
assert len(errors) == 1, errors
assert "1 point has a NaN or infinite scalar (the first at x, y, z = 2, 1, 0)" in errors[0], errors
assert grab(win).max() == 0, "a refused input drew something"

for i in range(box.GetNumberOfPoints()):
    scalars.SetValue(i, 1.0)
box.Modified()
win.Render()
assert len(errors) == 1, errors
assert grab(win).max() > 0, "the fixed input drew nothing"
print("ok")
