// Loads a volume with AdaptiveRT::IO, reduces it with vtkAdaptiveTetReducer and builds the tet
// mapper's engine mesh from the result: what a user's program does before rendering.
#include <DataLoader.h>
#include <Error.h>
#include <TetMesh.h>
#include <vtkAdaptiveTetReducer.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkTetRayCastMapper.h>
#include <vtkUnstructuredGrid.h>

#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: downstream VOLUME\n";
    return 2;
  }
  try
  {
    vtkNew<vtkAdaptiveTetReducer> reducer;
    reducer->SetInputData(art::LoadVolume(argv[1]));
    reducer->SetTargetTets(500);
    reducer->Update();
    const art::TetMesh mesh = art::TetMesh::FromVTK(reducer->GetOutput());
    vtkNew<vtkTetRayCastMapper> mapper;
    mapper->SetInputConnection(reducer->GetOutputPort());
    std::cout << "reduced to " << mesh.NumberOfTets() << " tets\n";
  }
  catch (const art::Error& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
