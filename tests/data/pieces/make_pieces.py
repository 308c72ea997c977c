"""Writes a small tet mesh as parallel pieces (.pvtu, as an MPI solver writes them: points
repeated at the piece boundaries) and as a two-block multiblock file (.vtm), for the loader's
tests: both must read as the one mesh of 320 tets and 125 vertices."""
import vtk

src = vtk.vtkRTAnalyticSource()
src.SetWholeExtent(-2, 2, -2, 2, -2, 2)
tri = vtk.vtkDataSetTriangleFilter()
tri.SetInputConnection(src.GetOutputPort())
pw = vtk.vtkXMLPUnstructuredGridWriter()
pw.SetFileName("pieces.pvtu")
pw.SetInputConnection(tri.GetOutputPort())
pw.SetNumberOfPieces(2)
pw.SetStartPiece(0)
pw.SetEndPiece(1)
pw.SetDataModeToAscii()
pw.Write()

tri.UpdatePiece(0, 1, 0)
whole = vtk.vtkUnstructuredGrid()
whole.DeepCopy(tri.GetOutput())
centres = vtk.vtkCellCenters()
centres.SetInputData(whole)
centres.Update()
halves = (vtk.vtkIdList(), vtk.vtkIdList())
for i in range(whole.GetNumberOfCells()):
    halves[centres.GetOutput().GetPoint(i)[0] < 0].InsertNextId(i)
blocks = vtk.vtkMultiBlockDataSet()
for k, ids in enumerate(halves):
    ex = vtk.vtkExtractCells()
    ex.SetInputData(whole)
    ex.SetCellList(ids)
    ex.Update()
    block = vtk.vtkUnstructuredGrid()
    block.DeepCopy(ex.GetOutput())
    block.GetCellData().RemoveArray("vtkOriginalCellIds")
    block.GetPointData().RemoveArray("vtkOriginalPointIds")
    blocks.SetBlock(k, block)
mw = vtk.vtkXMLMultiBlockDataWriter()
mw.SetFileName("blocks.vtm")
mw.SetInputData(blocks)
mw.SetDataModeToAscii()
mw.Write()
print(whole.GetNumberOfCells(), "tets,", whole.GetNumberOfPoints(), "points")
