"""vtkAdaptiveTetReducer on a vector array (a velocity), as VTK's volume mappers draw one.

VectorMode MAGNITUDE reduces each tuple's norm and COMPONENT one component: on a field
(f, 2 f, -2 f) with f linear and positive, the magnitude 3 f and component 1, 2 f, are linear and
must come back exact at every output point. Without VectorMode (and for a component past the last)
the filter says what to set; it used to say only 'extract a component first'.
"""
import adaptivert
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand, vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData


def f(x, y, z):
    return 2 * x + y + 0.5 * z + 20  # positive over the image


img = vtkImageData()
img.SetDimensions(7, 6, 5)
img.SetSpacing(1.0, 1.5, 2.0)
img.SetOrigin(-3, 0, 1)
velocity = vtkFloatArray()
velocity.SetName("velocity")
velocity.SetNumberOfComponents(3)
velocity.SetNumberOfTuples(img.GetNumberOfPoints())
for i in range(img.GetNumberOfPoints()):
    v = f(*img.GetPoint(i))
    velocity.SetTuple3(i, v, 2 * v, -2 * v)
img.GetPointData().AddArray(velocity)
density = vtkFloatArray()
density.SetName("density")
density.SetNumberOfTuples(img.GetNumberOfPoints())
density.Fill(1.0)
img.GetPointData().SetScalars(density)

errors = []


@calldata_type(VTK_STRING)
def on_error(obj, event, text):
    errors.append(text)


def reduce(mode=None, component=0):
    r = adaptivert.vtkAdaptiveTetReducer()
    r.SetInputData(img)
    r.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "velocity")
    if mode is not None:
        r.SetVectorMode(mode)
        r.SetVectorComponent(component)
    r.SetTargetTets(30)
    r.SetSolverTolerance(1e-14)
    r.AddObserver(vtkCommand.ErrorEvent, on_error)
    r.GetExecutive().AddObserver(vtkCommand.ErrorEvent, on_error)
    errors.clear()
    r.Update()
    return r


R = adaptivert.vtkAdaptiveTetReducer
for label, mode, component, scale, name in [("magnitude", R.MAGNITUDE, 0, 3.0, "velocity:magnitude"),
                                             ("component 1", R.COMPONENT, 1, 2.0, "velocity:1")]:
    r = reduce(mode, component)
    out = r.GetOutput()
    assert not errors and out.GetNumberOfCells() > 0, (label, errors)
    values = out.GetPointData().GetScalars()
    assert values.GetNumberOfComponents() == 1 and values.GetName() == name, (values.GetName(), name)
    worst = max(abs(values.GetTuple1(i) - scale * f(*out.GetPoint(i))) for i in range(out.GetNumberOfPoints()))
    print(f"{label}: {out.GetNumberOfCells()} tets, worst {worst:.2e}, RMS {r.GetRMSError():.2e}")
    assert worst < 1e-7, (label, worst)

for label, mode, component, words in [
        ("no VectorMode", None, 0, "'velocity' has 3 components; the reducer needs one (SetVectorMode"),
        ("component 3", R.COMPONENT, 3, "array 'velocity' has 3 components (0 .. 2), not a component 3")]:
    reduce(mode, component)
    print(f"{label}: {errors[:1]}")
    assert errors and words in errors[0], (label, errors)
print("ok")
