"""vtkTetRayCastMapper follows the mapper's ScalarMode as VTK's volume mappers do.

A 2 x 2 x 2 box seen straight on whose point scalars are 1 (green), a point array 'two' is 2
(red), its cell scalars 'cellz' are 0 (blue) and a cell array also named 'two' is 0: each mode
must show its array's colour at the closed-form opacity, switching modes re-renders; a vector
'velocity' shows its magnitude or a component under VectorMode; and a missing array, or a vector
one without VectorMode, is an error naming it. Needs a display (skips with exit 77).
"""
from mapper_scene import box_tets, constant_property, grab, look_down_z, offscreen_scene, require_display

require_display()

import numpy as np
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkFloatArray

import adaptivert

grid = box_tets()
ones = grid.GetPointData().GetScalars().GetName()


def array(name, n, value, components=1):
    a = vtkFloatArray()
    a.SetName(name)
    a.SetNumberOfComponents(components)
    a.SetNumberOfTuples(n)
    a.Fill(value)
    return a


grid.GetPointData().AddArray(array("two", grid.GetNumberOfPoints(), 2.0))
velocity = array("velocity", grid.GetNumberOfPoints(), 0.0, 3)
for i in range(grid.GetNumberOfPoints()):
    velocity.SetTuple3(i, 0.6, 0.8, 0.0)  # magnitude 1 (green); components 0.6, 0.8 and 0 (blue)
grid.GetPointData().AddArray(velocity)
grid.GetCellData().SetScalars(array("cellz", grid.GetNumberOfCells(), 0.0))
grid.GetCellData().AddArray(array("two", grid.GetNumberOfCells(), 0.0))

prop = constant_property((0, 0, 0), 0.5, unit=1.0)
ctf = prop.GetRGBTransferFunction()  # one colour a value: 0 blue, 1 green, 2 red
ctf.RemoveAllPoints()
ctf.AddRGBPoint(0, 0, 0, 1)
ctf.AddRGBPoint(1, 0, 1, 0)
ctf.AddRGBPoint(2, 1, 0, 0)

mapper = adaptivert.vtkTetRayCastMapper()
mapper.SetInputData(grid)
mapper.AutoAdjustSampleDistancesOff()
errors = []


@calldata_type(VTK_STRING)
def on_message(obj, event, text):
    if event == "ErrorEvent":
        errors.append(text)


mapper.AddObserver(vtkCommand.ErrorEvent, on_message)
mapper.AddObserver(vtkCommand.WarningEvent, on_message)  # cell scalars averaged to the points
volume, ren, win = offscreen_scene(mapper, prop, 60, 60)
look_down_z(ren, 1.5)


def centre():
    win.Render()
    img = grab(win) / 255.0
    return img[25:35, 25:35].reshape(-1, 3).mean(axis=0)


a = 1 - 0.5 ** 2  # opacity 0.5 per unit through 2 units of thickness
green, red, blue = np.array((0, a, 0)), np.array((a, 0, 0)), np.array((0, 0, a))
cases = [
    ("default", lambda: mapper.SetScalarModeToDefault(), green),
    ("UseCellData", lambda: mapper.SetScalarModeToUseCellData(), blue),
    ("UsePointData", lambda: mapper.SetScalarModeToUsePointData(), green),
    ("UsePointFieldData 'two'", lambda: (mapper.SetScalarModeToUsePointFieldData(), mapper.SelectScalarArray("two")), red),
    ("UseCellFieldData 'two'", lambda: (mapper.SetScalarModeToUseCellFieldData(), mapper.SelectScalarArray("two")), blue),
    ("UsePointFieldData by id 1", lambda: (mapper.SetScalarModeToUsePointFieldData(), mapper.SelectScalarArray(1)), red),
    ("back to default", lambda: mapper.SetScalarModeToDefault(), green),
    # A vector array as vtkSmartVolumeMapper's VectorMode draws it: its magnitude or one component.
    ("'velocity' magnitude", lambda: (mapper.SetScalarModeToUsePointFieldData(), mapper.SelectScalarArray("velocity"),
                                      mapper.SetVectorMode(mapper.MAGNITUDE)), green),
    ("'velocity' component 0", lambda: (mapper.SetVectorMode(mapper.COMPONENT), mapper.SetVectorComponent(0)),
     a * np.array((0, 0.6, 0.4))),
    ("'velocity' component 1", lambda: mapper.SetVectorComponent(1), a * np.array((0, 0.8, 0.2))),
    ("'velocity' component 2", lambda: mapper.SetVectorComponent(2), blue),
    ("'two' ignores VectorMode", lambda: mapper.SelectScalarArray("two"), red),
    ("active point scalars a vector", lambda: (mapper.SetScalarModeToDefault(), mapper.SetVectorMode(mapper.MAGNITUDE),
                                               grid.GetPointData().SetActiveScalars("velocity")), green),
    ("active point scalars again", lambda: (mapper.SetVectorMode(mapper.DISABLED),
                                            grid.GetPointData().SetActiveScalars(ones)), green),
]
for label, select, want in cases:
    select()
    got = centre()
    print(f"{label}: shown {np.round(got, 3)}, expected {np.round(want, 3)}")
    assert not errors, errors
    assert np.abs(got - want).max() < 3 / 255, (label, got, want)

for label, select, words in [
    ("missing", lambda: (mapper.SetScalarModeToUsePointFieldData(), mapper.SelectScalarArray("nope")),
     "no point array 'nope'"),
    ("vector", lambda: (mapper.SetScalarModeToUsePointFieldData(), mapper.SelectScalarArray("velocity")),
     "'velocity' has 3 components; the mapper renders one (SetVectorMode(vtkTetRayCastMapper::MAGNITUDE), or COMPONENT"),
    ("component 3", lambda: (mapper.SetVectorMode(mapper.COMPONENT), mapper.SetVectorComponent(3)),
     "array 'velocity' has 3 components (0 .. 2), not a component 3"),
    ("no cell scalars", lambda: (mapper.SetVectorMode(mapper.DISABLED), mapper.SetScalarModeToUseCellData(),
                                 grid.GetCellData().SetActiveScalars(None)),
     "no cell scalars"),
]:
    errors.clear()
    select()
    centre()
    print(f"{label}: {errors[:1]}")
    assert errors and words in errors[0], (label, errors)
print("ok")
