#include "DataLoader.h"
#include "Error.h"
#include "SurfaceColours.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMetaImageWriter.h>
#include <vtkNew.h>
#include <vtkSTLWriter.h>
#include <vtkSphereSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkFloatArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedShortArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkDataSetAttributes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
const std::string Data = std::string(ART_SOURCE_DIR) + "/data/";
const std::string Bad = std::string(ART_SOURCE_DIR) + "/tests/data/bad/";

// Loading must throw art::Error whose message names the file and contains `what`.
void ExpectError(const std::string& path, const std::string& what)
{
  try
  {
    art::Load(path);
    ADD_FAILURE() << path << " loaded without error";
  }
  catch (const art::Error& e)
  {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
  }
}
}

TEST(DataLoader, DefaultVolume)
{
  auto img = art::LoadVolume(Data + "ct-head-128.mha");
  int d[3];
  img->GetDimensions(d);
  EXPECT_EQ(d[0], 128);
  EXPECT_EQ(d[1], 128);
  EXPECT_EQ(d[2], 54);
  EXPECT_EQ(img->GetPointData()->GetScalars()->GetDataType(), VTK_SHORT);
}

TEST(DataLoader, DefaultSceneCountsTriangles)
{
  auto pd = art::LoadSurface(Data + "am_underworks.ply");
  EXPECT_EQ(pd->GetNumberOfPolys(), 2653);
}

TEST(DataLoader, KindByExtension)
{
  EXPECT_EQ(art::KindOf(Data + "ct-head-128.mha"), art::DataKind::Volume);
  EXPECT_EQ(art::KindOf(Data + "am_underworks.ply"), art::DataKind::Surface);
}

TEST(DataLoader, BadInputs)
{
  ExpectError(Bad + "nonexistent.mha", "no such file");
  ExpectError(Bad + "volume.xyz", "unknown file type");
  ExpectError(Bad + "truncated.mha", "truncated");
  ExpectError(Bad + "random.ply", "not a PLY file");
  ExpectError(Bad + "truncated.ply", "truncated");
  ExpectError(Bad + "dir.ply", "is a directory");
  ExpectError(Bad + "empty.vtp", "file is empty");
  ExpectError(Bad + "garbage.vti", "cannot read");
  ExpectError(Bad.substr(0, Bad.size() - 1), "no readable DICOM");
}

// VTK 9.1's OBJ reader trusts face indices: an out-of-range texture coordinate corrupted the heap
// (abort), an out-of-range normal gave garbage normals. Both are checked first; relative
// (negative) and absent indices stay valid.
// A data set of no points and no cells as VTK's XML writers save it (a filter's empty output) says
// it holds nothing; it said "cannot read: No Points element available in first piece found in
// file. Reading file may fail.", VTK's reader's own error.
TEST(DataLoader, EmptyXMLDataSetsSayTheyHoldNothing)
{
  const std::string mesh = std::string(ART_TEST_OUTPUT) + "/no-points.vtu";
  const std::string surface = std::string(ART_TEST_OUTPUT) + "/no-points.vtp";
  vtkNew<vtkXMLUnstructuredGridWriter> ug;
  ug->SetFileName(mesh.c_str());
  ug->SetInputData(vtkNew<vtkUnstructuredGrid>());
  ASSERT_EQ(ug->Write(), 1);
  vtkNew<vtkXMLPolyDataWriter> pd;
  pd->SetFileName(surface.c_str());
  pd->SetInputData(vtkNew<vtkPolyData>());
  ASSERT_EQ(pd->Write(), 1);
  ExpectError(mesh, "holds no cells");
  ExpectError(surface, "holds no polygons");
}

// A multiblock file of polydata blocks (a CAD assembly, a surface ParaView extracted from blocks)
// is a triangle scene of every block's polygons; it was read as a mesh and refused ("holds no 3-D
// cells ... a surface renders from .vtp, .ply, .obj or .stl"). A .vtm of grids stays a mesh.
TEST(DataLoader, MultiBlockOfSurfacesIsASurface)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/surfaces.vtm";
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> triangle;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(2, 0, 0);
  pts->InsertNextPoint(3, 0, 0);
  pts->InsertNextPoint(2, 1, 0);
  triangle->SetPoints(pts);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, ids);
  triangle->SetPolys(polys);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, sphere->GetOutput());
  blocks->SetBlock(1, triangle);
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetFileName(path.c_str());
  w->SetInputData(blocks);
  ASSERT_EQ(w->Write(), 1);
  EXPECT_EQ(art::KindOf(path), art::DataKind::Surface);
  auto pd = art::LoadSurface(path);
  EXPECT_EQ(pd->GetNumberOfPolys(), sphere->GetOutput()->GetNumberOfPolys() + 1);
  EXPECT_EQ(pd->GetBounds()[1], 3.0);
  EXPECT_EQ(art::KindOf(std::string(ART_SOURCE_DIR) + "/tests/data/pieces/blocks.vtm"), art::DataKind::Mesh);
}

// A UTF-8 byte-order mark (some Windows exporters write one) before an OBJ's or a material
// library's first line is skipped: the first vertex was lost ("line 4: a face refers to vertex 3
// of 2 defined") and the first material. PLY and STL text, read by VTK, are one clear line.
TEST(DataLoader, ByteOrderMarks)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  const std::string bom = "\xEF\xBB\xBF";
  std::ofstream(dir + "bom.mtl") << bom << "newmtl red\nKd 1 0 0\n";
  std::ofstream(dir + "bom.obj") << bom << "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib bom.mtl\nusemtl red\nf 1 2 3\n";
  auto pd = art::LoadSurface(dir + "bom.obj");
  EXPECT_EQ(pd->GetNumberOfPoints(), 3);
  EXPECT_EQ(pd->GetNumberOfPolys(), 1);
  ASSERT_NE(pd->GetCellData()->GetScalars(), nullptr);
  EXPECT_EQ(pd->GetCellData()->GetScalars()->GetComponent(0, 0), 255);
  std::ofstream(dir + "bom.ply") << bom << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                 << "property float y\nproperty float z\nelement face 1\n"
                                 << "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  ExpectError(dir + "bom.ply", "starts with a UTF-8 byte-order mark before 'ply'");
  std::ofstream(dir + "bom.stl") << bom << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                 << "vertex 0 1 0\nendloop\nendfacet\nendsolid x\n";
  ExpectError(dir + "bom.stl", "starts with a UTF-8 byte-order mark");
}

// A folder of 2-D slices (a micro-CT's TIFF stack) is read as a stack; one whose slices are not
// images names the slice at fault.
TEST(DataLoader, ImageStackFolderIsNamed)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/tif-stack";
  std::filesystem::create_directories(dir);
  for (const char* name : { "/s0001.tif", "/s0002.tif" })
  {
    std::ofstream(dir + name) << "II*";
  }
  // A folder of slices is read as a stack (OtherFormats); these three bytes are no TIFF.
  ExpectError(dir, "s0001.tif: is not a TIFF file libtiff opens");
  ExpectError(dir + "/s0001.tif", "is not a TIFF file libtiff opens");
}

TEST(DataLoader, ObjFaceIndicesAreChecked)
{
  ExpectError(Bad + "texcoord-out-of-range.obj", "line 11: a face refers to texture coordinate 5 of 4 defined");
  ExpectError(Bad + "normal-out-of-range.obj", "line 6: a face refers to normal 3 of 1 defined");
  const std::string good = std::string(ART_TEST_OUTPUT) + "/relative-indices.obj";
  {
    std::ofstream f(good);
    f << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//1 3//1\nv 1 1 0\nf 2//1 -1//-1 3//1\n";
  }
  auto pd = art::LoadSurface(good);
  EXPECT_EQ(pd->GetNumberOfPolys(), 2);
  {
    std::ofstream f(good);
    f << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n";
  }
  ExpectError(good, "line 4: a face refers to vertex -4 of 3 defined");
}

// Architectural and CAD exports mix face forms in one file. vtkOBJReader (VTK 9.1) kept 1 of these
// 5 faces (it drops faces without the normals or texture coordinates another face has) and failed
// on the CRLF copy; every face is kept now, in both.
TEST(DataLoader, ObjKeepsEveryFace)
{
  const std::string text = "# exported by C:\\cad\\ \\\n"
                           "mtllib walls.mtl\no wall\n"
                           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 -1 0\n"
                           "g front\nusemtl brick\ns 1\n"
                           "f 1//1 2//1 3//1\n"
                           "f 1 3 4\n"
                           "s off\n"
                           "f 1/1 2/2 5/3\n"
                           "f -6/-3/-1 -5/-2/-1 -1/-1/-1 \\\n  -2\n"
                           "f 3 4 5 \\\n6 2 # a pentagon\n";
  for (const bool crlf : { false, true })
  {
    std::string body = text;
    if (crlf)
    {
      for (std::size_t p = body.find('\n'); p != std::string::npos; p = body.find('\n', p + 2))
      {
        body.insert(p, "\r");
      }
    }
    const std::string path = std::string(ART_TEST_OUTPUT) + (crlf ? "/mixed-faces-crlf.obj" : "/mixed-faces.obj");
    std::ofstream(path, std::ios::binary) << body;
    auto pd = art::LoadSurface(path);
    ASSERT_EQ(pd->GetNumberOfPolys(), 5) << path;
    EXPECT_EQ(pd->GetNumberOfPoints(), 6) << path; // no attribute on every face: vertices as in the file
    EXPECT_EQ(pd->GetPointData()->GetNormals(), nullptr);
    const std::vector<std::vector<vtkIdType>> expected = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 1, 4 }, { 0, 1, 5, 4 },
      { 2, 3, 4, 5, 1 } };
    vtkIdType triangles = 0;
    for (vtkIdType c = 0; c < 5; ++c)
    {
      vtkIdType n;
      const vtkIdType* ids;
      pd->GetPolys()->GetCellAtId(c, n, ids);
      EXPECT_EQ(std::vector<vtkIdType>(ids, ids + n), expected[c]) << "face " << c << " of " << path;
      triangles += n - 2;
    }
    EXPECT_EQ(triangles, 8);
    double b[6];
    pd->GetBounds(b);
    EXPECT_EQ(b[1], 1);
    EXPECT_EQ(b[5], 1);
  }
}

// Faces with normals on every corner keep them; a vertex whose faces give it different normals is
// split there (a crease), one whose faces agree is shared.
TEST(DataLoader, ObjNormalsSplitOnlyAtCreases)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/crease.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 1 0 0\n"
                         "f 1//1 2//2 3//3\nf 2//2 4//4 3//3\n";
  auto pd = art::LoadSurface(path);
  EXPECT_EQ(pd->GetNumberOfPolys(), 2);
  EXPECT_EQ(pd->GetNumberOfPoints(), 4); // normal index = vertex index: nothing to split
  ASSERT_NE(pd->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(pd->GetPointData()->GetNormals()->GetTuple3(3)[0], 1);

  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 0 0 1\nvn 1 0 0\n"
                         "f 1//1 2//1 3//1\nf 2//2 4//2 3//1\n";
  pd = art::LoadSurface(path);
  EXPECT_EQ(pd->GetNumberOfPolys(), 2);
  EXPECT_EQ(pd->GetNumberOfPoints(), 5); // vertex 2 has two normals, vertex 3 one
  vtkIdType n;
  const vtkIdType* ids;
  pd->GetPolys()->GetCellAtId(1, n, ids);
  EXPECT_EQ(std::vector<vtkIdType>(ids, ids + n), (std::vector<vtkIdType>{ 3, 4, 2 }));

  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n";
  ExpectError(path, "line 4: a face needs at least 3 corners, it has 2");
  std::ofstream(path) << "v 0 0 0\nv 1 0\n";
  ExpectError(path, "line 2: expected 3 numbers, found 2");
}

// Photogrammetry exports (Meshroom, Agisoft) colour vertices as "v x y z r g b"; vtkOBJReader
// dropped the colours. They become 8-bit RGB scalars (0..1 or 0..255 in the file), which render
// and VTK's mappers draw; a file where some vertices lack a colour keeps none.
TEST(DataLoader, ObjVertexColours)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/colours.obj";
  std::ofstream(path) << "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
  auto pd = art::LoadSurface(path);
  vtkDataArray* rgb = pd->GetPointData()->GetScalars();
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(rgb->GetNumberOfComponents(), 3);
  EXPECT_EQ(rgb->GetComponent(0, 0), 255);
  EXPECT_EQ(rgb->GetComponent(1, 1), 128);
  EXPECT_EQ(rgb->GetComponent(2, 2), 255);
  std::ofstream(path) << "v 0 0 0 255 0 0\nv 1 0 0 0 128 0\nv 0 1 0 0 0 255\nf 1 2 3\n";
  pd = art::LoadSurface(path);
  rgb = pd->GetPointData()->GetScalars();
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->GetComponent(1, 1), 128);
  std::ofstream(path) << "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1 1\nf 1 2 3\n"; // one without, one with a w
  EXPECT_EQ(art::LoadSurface(path)->GetPointData()->GetScalars(), nullptr);
}

// Face colours (tests/data/colours/face-colours.ply: a cube, one colour a face) were dropped by
// render and the viewer. Each triangle gets corners of its own with its face's colour; a surface
// whose points carry colours is drawn as it is.
TEST(DataLoader, FaceColoursMoveOntoCorners)
{
  auto cube = art::LoadSurface(std::string(ART_SOURCE_DIR) + "/tests/data/colours/face-colours.ply");
  EXPECT_TRUE(art::PointColours(cube).empty());
  auto split = art::WithColoursOnPoints(cube);
  ASSERT_EQ(split->GetNumberOfPolys(), 12);
  ASSERT_EQ(split->GetNumberOfPoints(), 36);
  const auto rgb = art::PointColours(split);
  ASSERT_EQ(rgb.size(), 36u);
  // The first face (z = 0) is red, the sixth (x = 0) magenta: two triangles each, in file order.
  for (int c = 0; c < 6; ++c)
  {
    EXPECT_EQ(rgb[c][0], 1.f);
    EXPECT_EQ(rgb[c][1], 0.f);
    EXPECT_EQ(rgb[c][2], 0.f);
    double p[3];
    split->GetPoint(c, p);
    EXPECT_EQ(p[2], 0.0);
    EXPECT_EQ(rgb[30 + c][0], 1.f);
    EXPECT_EQ(rgb[30 + c][1], 0.f);
    EXPECT_EQ(rgb[30 + c][2], 1.f);
    split->GetPoint(30 + c, p);
    EXPECT_EQ(p[0], 0.0);
  }
  auto corners = art::LoadSurface(std::string(ART_SOURCE_DIR) + "/tests/data/colours/corner-colours.ply");
  EXPECT_EQ(art::WithColoursOnPoints(corners).Get(), corners.Get());
  EXPECT_EQ(art::PointColours(corners).size(), 24u);
}

// OBJ faces coloured by materials (usemtl, with Kd in the mtllib libraries) were drawn grey: the
// diffuse colours become 8-bit cell colours when every face has one.
TEST(DataLoader, ObjMaterialColours)
{
  auto cube = art::LoadSurface(std::string(ART_SOURCE_DIR) + "/tests/data/colours/cube.obj");
  vtkDataArray* rgb = cube->GetCellData()->GetScalars();
  ASSERT_NE(rgb, nullptr);
  ASSERT_EQ(rgb->GetNumberOfTuples(), 6);
  const double want[6][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 }, { 255, 255, 0 }, { 0, 255, 255 },
    { 255, 0, 255 } };
  for (int c = 0; c < 6; ++c)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(rgb->GetComponent(c, k), want[c][k]) << "face " << c;
    }
  }
  // A line before the faces keeps the cell order (verts, lines, polys) of its colours.
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  std::ofstream(dir + "m.mtl") << "newmtl a\nKd 0 0 1\nnewmtl b\nKd 1 0.5 0\n";
  std::ofstream(dir + "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nl 1 2\n";
  auto pd = art::LoadSurface(dir + "m.obj");
  ASSERT_NE(pd->GetCellData()->GetScalars(), nullptr);
  EXPECT_EQ(pd->GetCellData()->GetScalars()->GetComponent(0, 1), 128); // the line: b
  EXPECT_EQ(pd->GetCellData()->GetScalars()->GetComponent(1, 2), 255); // the face: a
  // A face without a material, or a material without Kd, leaves the file without face colours.
  std::ofstream(dir + "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl a\nf 1 3 2\n";
  EXPECT_EQ(art::LoadSurface(dir + "m.obj")->GetCellData()->GetScalars(), nullptr);
  std::ofstream(dir + "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl c\nf 1 2 3\n";
  EXPECT_EQ(art::LoadSurface(dir + "m.obj")->GetCellData()->GetScalars(), nullptr);
}

// 16-bit colours (LAS point clouds through PDAL) and floating colours in 0..255 were drawn white
// (only 8-bit colours were scaled); a NaN channel is black.
TEST(DataLoader, PointColoursOfEveryRange)
{
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->SetNumberOfPoints(2);
  pd->SetPoints(pts);
  vtkNew<vtkUnsignedShortArray> wide;
  wide->SetNumberOfComponents(3);
  wide->InsertNextTuple3(65535, 0, 32768);
  wide->InsertNextTuple3(0, 65535, 0);
  pd->GetPointData()->SetScalars(wide);
  auto c = art::PointColours(pd);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0][0], 1.f);
  EXPECT_NEAR(c[0][2], 0.5, 1e-4);
  EXPECT_EQ(c[1][1], 1.f);
  vtkNew<vtkFloatArray> big;
  big->SetNumberOfComponents(3);
  big->InsertNextTuple3(255, 51, 0);
  big->InsertNextTuple3(0, 0, 127.5);
  pd->GetPointData()->SetScalars(big);
  c = art::PointColours(pd);
  EXPECT_EQ(c[0][0], 1.f);
  EXPECT_NEAR(c[0][1], 0.2, 1e-6);
  EXPECT_NEAR(c[1][2], 0.5, 1e-6);
  vtkNew<vtkFloatArray> unit;
  unit->SetNumberOfComponents(3);
  unit->InsertNextTuple3(1, 0.25, 0);
  unit->InsertNextTuple3(std::nan(""), 0, 0.5);
  pd->GetPointData()->SetScalars(unit);
  c = art::PointColours(pd);
  EXPECT_EQ(c[0][1], 0.25f);
  EXPECT_EQ(c[1][2], 0.5f);
  EXPECT_EQ(c[1][0], 0.f);
}

// Survey and CAD exports sit far from the origin: vtkOBJReader kept float points, so a 1-unit
// sphere 2.5e7 out lost every triangle to rounding ("has no triangles to render"). Points are double.
TEST(DataLoader, ObjKeepsDoublePrecision)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/far.obj";
  std::ofstream(path) << "v 25000000.125 -30000000.5 1000.25\nv 25000000.375 -30000000.5 1000.25\n"
                         "v 25000000.125 -30000000.25 1000.25\nf 1 2 3\n";
  auto pd = art::LoadSurface(path);
  double p[3];
  pd->GetPoint(1, p);
  EXPECT_EQ(p[0], 25000000.375);
  pd->GetPoint(2, p);
  EXPECT_EQ(p[1], -30000000.25);
}

// A PLY of double coordinates (CloudCompare and photogrammetry exports in UTM) kept only
// vtkPLYReader's floats: a 0.25 m triangle 2.5e7 m out collapsed ("has no triangles to render").
// Floating-point vertex colours (plyfile and numpy writers use them) were cast to 8 bits by
// vtkPLYReader: 1.0 read as 1 of 255, so a red mesh rendered black. They are kept as written, in
// 0..1 (or scaled from 0..255 when a value exceeds 1), ASCII and binary alike.
TEST(DataLoader, PlyKeepsFloatColours)
{
  const float rgb[3][3] = { { 1.f, 0.f, 0.f }, { 0.25f, 0.5f, 0.75f }, { 0.f, 1.f, 1.f } };
  const std::string header = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "property float red\nproperty float green\nproperty float blue\nelement face 1\n"
                             "property list uchar int vertex_indices\nend_header\n";
  const std::string ascii = std::string(ART_TEST_OUTPUT) + "/float-colours-ascii.ply";
  {
    std::ofstream f(ascii);
    f << "ply\nformat ascii 1.0\n" << header;
    for (int i = 0; i < 3; ++i)
    {
      f << i % 2 << " " << i / 2 << " 0 " << rgb[i][0] << " " << rgb[i][1] << " " << rgb[i][2] << "\n";
    }
    f << "3 0 1 2\n";
  }
  const std::string binary = std::string(ART_TEST_OUTPUT) + "/float-colours-binary.ply";
  {
    std::ofstream f(binary, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\n" << header;
    for (int i = 0; i < 3; ++i)
    {
      const float xyz[3] = { float(i % 2), float(i / 2), 0.f };
      f.write(reinterpret_cast<const char*>(xyz), 12);
      f.write(reinterpret_cast<const char*>(rgb[i]), 12);
    }
    const int ids[3] = { 0, 1, 2 };
    f.put(3);
    f.write(reinterpret_cast<const char*>(ids), 12);
  }
  for (const std::string& path : { ascii, binary })
  {
    const auto colours = art::PointColours(art::LoadSurface(path));
    ASSERT_EQ(colours.size(), 3u) << path;
    for (int i = 0; i < 3; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(colours[i][c], rgb[i][c]) << path << " vertex " << i;
      }
    }
  }
}

TEST(DataLoader, PlyKeepsDoubleCoordinates)
{
  const double pts[4][3] = { { 25000000.125, -30000000.5, 1000.25 }, { 25000000.375, -30000000.5, 1000.25 },
    { 25000000.125, -30000000.25, 1000.25 }, { 25000000.375, -30000000.25, 1000.5 } };
  const std::string header = "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
                             "property uchar flag\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string ascii = std::string(ART_TEST_OUTPUT) + "/far-ascii.ply";
  {
    std::ofstream f(ascii);
    f << "ply\nformat ascii 1.0\n" << header;
    f.precision(17);
    for (const auto& p : pts)
    {
      f << p[0] << " " << p[1] << " " << p[2] << " 7\n";
    }
    f << "3 0 1 2\n3 1 3 2\n";
  }
  const std::string binary = std::string(ART_TEST_OUTPUT) + "/far-binary.ply";
  {
    std::ofstream f(binary, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\n" << header;
    for (const auto& p : pts)
    {
      f.write(reinterpret_cast<const char*>(p), 24);
      f.put(7);
    }
    for (const int face : { 0, 1 })
    {
      const int ids[2][3] = { { 0, 1, 2 }, { 1, 3, 2 } };
      f.put(3);
      f.write(reinterpret_cast<const char*>(ids[face]), 12);
    }
  }
  for (const std::string& path : { ascii, binary })
  {
    auto pd = art::LoadSurface(path);
    ASSERT_EQ(pd->GetNumberOfPoints(), 4) << path;
    EXPECT_EQ(pd->GetNumberOfPolys(), 2) << path;
    for (int i = 0; i < 4; ++i)
    {
      double p[3];
      pd->GetPoint(i, p);
      EXPECT_EQ(p[0], pts[i][0]) << path;
      EXPECT_EQ(p[1], pts[i][1]) << path;
      EXPECT_EQ(p[2], pts[i][2]) << path;
    }
  }
}

TEST(DataLoader, WrongKindForTheCall)
{
  EXPECT_THROW(art::LoadSurface(Data + "ct-head-128.mha"), art::Error);
  EXPECT_THROW(art::LoadVolume(Data + "am_underworks.ply"), art::Error);
}

// VTK 9.1 reads a truncated binary STL's first triangles without a word (and random bytes as
// triangles 1e38 wide); the triangle count in the header is checked against the file's size.
TEST(DataLoader, TruncatedBinaryStl)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  const std::string full = std::string(ART_TEST_OUTPUT) + "/sphere-binary.stl";
  vtkNew<vtkSTLWriter> w;
  w->SetInputConnection(sphere->GetOutputPort());
  w->SetFileTypeToBinary();
  w->SetFileName(full.c_str());
  ASSERT_TRUE(w->Write());
  const long long polys = sphere->GetOutput()->GetNumberOfPolys();
  EXPECT_EQ(art::LoadSurface(full)->GetNumberOfPolys(), polys);
  const std::string cut = std::string(ART_TEST_OUTPUT) + "/sphere-truncated.stl";
  std::filesystem::copy_file(full, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, 1000);
  ExpectError(cut, "the header counts " + std::to_string(polys) + " triangles");
  // A text STL is still VTK's to read.
  w->SetFileTypeToASCII();
  w->SetFileName(cut.c_str());
  ASSERT_TRUE(w->Write());
  EXPECT_EQ(art::LoadSurface(cut)->GetNumberOfPolys(), polys);
}

// MetaImage headers with numbers that do not fit: 2^32 per axis wrapped the voxel count to 0
// (the size check passed), and a channel count 'abc' ended as the one word "stoi".
TEST(DataLoader, MetaImageHeaderNumbers)
{
  auto write = [](const std::string& name, const std::string& lines) {
    const std::string p = std::string(ART_TEST_OUTPUT) + "/" + name;
    std::ofstream(p, std::ios::binary) << "ObjectType = Image\nNDims = 3\n" << lines
                                       << "ElementType = MET_UCHAR\nElementDataFile = LOCAL\nABCDEFGH";
    return p;
  };
  ExpectError(write("wrap.mha", "DimSize = 4294967296 4294967296 4294967296\n"), "DimSize '4294967296 4294967296 4294967296' is too large");
  ExpectError(write("channels.mha", "DimSize = 2 2 2\nElementNumberOfChannels = abc\n"),
    "ElementNumberOfChannels is not a whole number: 'abc'");
  ExpectError(write("channels0.mha", "DimSize = 2 2 2\nElementNumberOfChannels = 0\n"), "ElementNumberOfChannels must be 1..1024");
  EXPECT_EQ(art::LoadVolume(write("fine.mha", "DimSize = 2 2 2\n"))->GetNumberOfPoints(), 8);
}

// An image whose points carry no value to render said "holds no voxels (empty or unreadable
// volume)": a legacy file with only field data, and one with only a vector array, say what they hold.
TEST(DataLoader, VoxelsWithoutValues)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                           "ORIGIN 0 0 0\nSPACING 1 1 1\n";
  std::ofstream(dir + "field-only.vtk") << head << "FIELD FieldData 1\ntime 1 1 float\n1.5\n";
  ExpectError(dir + "field-only.vtk", "has 8 voxels but no values on them (only field data: time)");
  std::ofstream(dir + "vectors-only.vtk") << head << "POINT_DATA 8\nVECTORS grad float\n" << "1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0 1 0 0\n";
  ExpectError(dir + "vectors-only.vtk", "has no one-component point array to take as the voxels (point arrays: grad; "
                                        "choose a vector's magnitude or component with --array grad:magnitude or grad:0 .. grad:2)");
}

// A vector array (a simulation's velocity, an RGB volume) was refused everywhere: "NAME:magnitude"
// and "NAME:N" (or X, Y, Z) take what VTK's volume mappers draw of it (VectorMode), as one-component
// scalars.
TEST(DataLoader, VectorMagnitudeOrComponent)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/velocity.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                         "ORIGIN 0 0 0\nSPACING 1 1 1\nPOINT_DATA 8\nSCALARS density float 1\nLOOKUP_TABLE default\n"
                         "0 1 2 3 4 5 6 7\nVECTORS velocity float\n"
                         "3 4 0  0 0 2  1 2 2  -6 8 0  0 0 0  1 0 0  0 -5 12  2 3 6\n";
  const double magnitude[8] = { 5, 2, 3, 10, 0, 1, 13, 7 };
  for (const char* spec : { "velocity:magnitude", "velocity:Magnitude", "velocity:mag" })
  {
    auto v = art::LoadVolume(path, spec);
    vtkDataArray* s = v->GetPointData()->GetScalars();
    ASSERT_EQ(s->GetNumberOfComponents(), 1);
    EXPECT_STREQ(s->GetName(), "velocity:magnitude");
    for (int i = 0; i < 8; ++i)
    {
      EXPECT_DOUBLE_EQ(s->GetTuple1(i), magnitude[i]) << spec << " voxel " << i;
    }
  }
  auto y = art::LoadVolume(path, "velocity:1"), Y = art::LoadVolume(path, "velocity:Y");
  const double ys[8] = { 4, 0, 2, 8, 0, 0, -5, 3 };
  for (int i = 0; i < 8; ++i)
  {
    EXPECT_EQ(y->GetPointData()->GetScalars()->GetTuple1(i), ys[i]);
    EXPECT_EQ(Y->GetPointData()->GetScalars()->GetTuple1(i), ys[i]);
  }
  // The plain array is still read as it is; a one-component array's component 0 is itself.
  auto d = art::LoadVolume(path, "density"), d0 = art::LoadVolume(path, "density:0");
  EXPECT_EQ(d->GetPointData()->GetScalars()->GetTuple1(7), 7);
  EXPECT_EQ(d0->GetPointData()->GetScalars()->GetTuple1(7), 7);
  auto expectError = [&](const std::string& array, const std::string& what) {
    try
    {
      art::RequireOneComponent(art::LoadVolume(path, array), path);
      ADD_FAILURE() << array << ": no error";
    }
    catch (const art::Error& e)
    {
      EXPECT_NE(std::string(e.what()).find(path + ": " + what), std::string::npos) << e.what();
    }
  };
  expectError("velocity:3", "array 'velocity' has 3 components (0 .. 2), not a component 3");
  expectError("speed:magnitude", "has no point array 'speed'");
  expectError("velocity", "the scalars 'velocity' have 3 components; one is needed (choose with --array "
                          "velocity:magnitude or velocity:0 .. velocity:2, or another array)");
}

// Compressed MetaImage data that does not fit its header was read silently wrong by
// vtkMetaImageReader: all zeros without CompressedDataSize (data in the header's file) or when the
// bytes are not zlib, uninitialised voxels when it inflates short. The compressed bytes come from
// VTK's own writer; the headers are edited.
TEST(DataLoader, MetaImageCompressedData)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  vtkNew<vtkImageData> img;
  img->SetDimensions(6, 5, 4);
  img->AllocateScalars(VTK_SHORT, 1);
  for (vtkIdType i = 0; i < 120; ++i)
  {
    img->GetPointData()->GetScalars()->SetTuple1(i, i % 50 + 1);
  }
  vtkNew<vtkMetaImageWriter> w;
  w->SetInputData(img);
  w->SetFileName((dir + "packed.mha").c_str());
  w->SetCompression(true);
  w->Write();
  std::ifstream in(dir + "packed.mha", std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t body = file.find("ElementDataFile = LOCAL\n") + 24;
  ASSERT_NE(file.find("CompressedDataSize"), std::string::npos);
  EXPECT_EQ(art::LoadVolume(dir + "packed.mha")->GetPointData()->GetScalars()->GetRange()[0], 1);
  auto edited = [&](const std::string& name, const std::string& from, const std::string& to, const std::string& data) {
    std::string h = file.substr(0, body);
    const std::size_t at = h.find(from);
    h.replace(at, h.find('\n', at) - at, to);
    std::ofstream(dir + name, std::ios::binary) << h << data;
    return dir + name;
  };
  const std::string packed = file.substr(body);
  ExpectError(edited("no-size.mha", "CompressedDataSize", "Comment = no size", packed),
    "compressed data without CompressedDataSize, which VTK's MetaImage reader reads as zeros: add "
    "'CompressedDataSize = " + std::to_string(packed.size()) + "' to the header");
  ExpectError(edited("inflates-short.mha", "DimSize", "DimSize = 6 5 8", packed),
    "the compressed data inflates to 240 bytes; the header's DimSize and ElementType need 480");
  ExpectError(edited("not-zlib.mha", "CompressedDataSize", "CompressedDataSize = " + std::to_string(packed.size()),
                std::string(packed.size(), 'z')),
    "the compressed data is not readable zlib data");
  // In a data file of its own, the size may go: VTK takes the file's.
  std::ofstream(dir + "own.zraw", std::ios::binary) << packed;
  std::string own = file.substr(0, body);
  const std::size_t size = own.find("CompressedDataSize");
  own.erase(size, own.find('\n', size) + 1 - size);
  own.replace(own.find("LOCAL"), 5, "own.zraw");
  std::ofstream(dir + "own.mhd", std::ios::binary) << own;
  EXPECT_EQ(art::LoadVolume(dir + "own.mhd")->GetPointData()->GetScalars()->GetRange()[1], 50);
}

// Pieces saved from a parallel run with ghost levels repeat their neighbours' boundary cells,
// marked DUPLICATECELL in vtkGhostType: appended whole, the copies overlapped and the mesh was
// refused. Two pieces of a row of unit hexahedra, each with one ghost of the other's, read as the
// row once, without the marks.
TEST(DataLoader, ParallelPiecesDropTheirGhostCells)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/ghosts/";
  std::filesystem::create_directories(dir);
  auto piece = [&dir](const std::string& name, int first, int cells, int ghost) {
    vtkNew<vtkPoints> pts;
    vtkNew<vtkFloatArray> x;
    x->SetName("x");
    for (int i = first; i <= first + cells; ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        pts->InsertNextPoint(i, k & 1, k >> 1);
        x->InsertNextValue(static_cast<float>(i));
      }
    }
    vtkNew<vtkUnstructuredGrid> g;
    g->SetPoints(pts);
    g->GetPointData()->SetScalars(x);
    vtkNew<vtkUnsignedCharArray> marks;
    marks->SetName(vtkDataSetAttributes::GhostArrayName());
    for (int c = 0; c < cells; ++c)
    {
      const vtkIdType a = 4 * c, b = 4 * (c + 1);
      const vtkIdType hex[8] = { a, b, b + 1, a + 1, a + 2, b + 2, b + 3, a + 3 };
      g->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      marks->InsertNextValue(first + c == ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
    }
    g->GetCellData()->AddArray(marks);
    vtkNew<vtkXMLUnstructuredGridWriter> w;
    w->SetInputData(g);
    w->SetFileName((dir + name).c_str());
    ASSERT_TRUE(w->Write());
  };
  piece("p0.vtu", 0, 3, 2); // cells 0, 1 and a ghost of 2
  piece("p1.vtu", 1, 3, 1); // a ghost of 1, cells 2, 3
  std::ofstream(dir + "run.pvtu") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
                                     "<PUnstructuredGrid GhostLevel=\"1\">\n<PPointData Scalars=\"x\"><PDataArray type=\"Float32\" "
                                     "Name=\"x\"/></PPointData>\n<PCellData><PDataArray type=\"UInt8\" Name=\"vtkGhostType\"/>"
                                     "</PCellData>\n<PPoints><PDataArray type=\"Float32\" NumberOfComponents=\"3\"/></PPoints>\n"
                                     "<Piece Source=\"p0.vtu\"/>\n<Piece Source=\"p1.vtu\"/>\n</PUnstructuredGrid>\n</VTKFile>\n";
  auto mesh = art::LoadMesh(dir + "run.pvtu");
  ASSERT_EQ(mesh->GetNumberOfCells(), 4);
  EXPECT_EQ(mesh->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()), nullptr);
  double b[6];
  mesh->GetBounds(b);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 4);
}

// A time series (ParaView's .pvd collection, a .series file) said "unknown file type '.pvd'"; the
// error now says what it is and names its first file.
TEST(DataLoader, TimeSeriesNamesItsFirstFile)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  std::ofstream(dir + "run.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                                    "<Collection>\n<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"run/step_0.vtu\"/>\n"
                                    "<DataSet timestep=\"0.5\" part=\"0\" file=\"run/step_1.vtu\"/>\n</Collection>\n</VTKFile>\n";
  ExpectError(dir + "run.pvd", "is a time series of 2 data files (ParaView .pvd collection), which the tools do not "
                               "step through: give one of its files, e.g. '" + dir + "run/step_0.vtu' (time 0.25)");
  std::ofstream(dir + "run.vtu.series") << R"({ "file-series-version" : "1.0", "files" : [ { "name" : "a.vtu", "time" : 0 }, )"
                                        << R"({ "name" : "b.vtu", "time" : 1.5 } ] })";
  ExpectError(dir + "run.vtu.series", "is a time series of 2 data files (.series file), which the tools do not step "
                                      "through: give one of its files, e.g. '" + dir + "a.vtu' (time 0)");
  std::ofstream(dir + "none.pvd") << "<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>\n";
  ExpectError(dir + "none.pvd", "is a time series (ParaView .pvd collection) that names no data files");
}

// A 4-D MetaImage (a time series, as ITK and 3D Slicer write them): vtkMetaImageReader killed the
// process with a heap corrupted ("double free or corruption"), even with a fourth axis of one sample.
TEST(DataLoader, MetaImageFourAxes)
{
  auto write = [](const std::string& name, const std::string& dims, int bytes) {
    const std::string p = std::string(ART_TEST_OUTPUT) + "/" + name;
    std::ofstream(p, std::ios::binary) << "ObjectType = Image\nNDims = 4\nDimSize = " << dims
                                       << "\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n"
                                       << std::string(bytes, '\x07');
    return p;
  };
  ExpectError(write("time.mha", "6 5 4 3", 360),
    "a 4-D image (DimSize 6 5 4 3): only 3-D volumes are read; save one volume (a time step or channel) as its own 3-D file");
  ExpectError(write("one-step.mha", "6 5 4 1", 120), "a 4-D image (DimSize 6 5 4 1)");
}

// vtkPLYReader (VTK 9.1) segfaulted on a face index past the vertex count and on an ASCII face
// line shorter than its count; the body is read through once before VTK sees it.
// A MetaImage slice series (ElementDataFile = LIST, or "pattern first last step"): vtkMetaImageReader
// zero-filled the slices of a missing or short file without a word. Every file must exist and
// together hold the data; a pattern is a printf format with one integer conversion.
TEST(DataLoader, MetaImageFileSeries)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/mha-series/";
  std::filesystem::create_directories(dir);
  for (short k = 0; k < 3; ++k)
  {
    std::ofstream f(dir + "s" + std::to_string(k) + ".raw", std::ios::binary);
    for (short i = 0; i < 12; ++i)
    {
      const short v = 100 * k + i;
      f.write(reinterpret_cast<const char*>(&v), 2);
    }
  }
  auto header = [&dir](const std::string& name, const std::string& dims, const std::string& data) {
    std::ofstream(dir + name) << "ObjectType = Image\nNDims = 3\nDimSize = " << dims
                              << "\nElementType = MET_SHORT\nElementDataFile = " << data;
    return dir + name;
  };
  auto img = art::LoadVolume(header("list.mhd", "4 3 3", "LIST\ns0.raw\ns1.raw\ns2.raw\n"));
  EXPECT_EQ(img->GetPointData()->GetScalars()->GetRange()[1], 211);
  img = art::LoadVolume(header("pattern.mhd", "4 3 3", "s%d.raw 0 2 1\n"));
  EXPECT_EQ(img->GetPointData()->GetScalars()->GetTuple1(35), 211);
  ExpectError(header("missing.mhd", "4 3 3", "LIST\ns0.raw\ns1.raw\nnope.raw\n"),
    "data file 'nope.raw' of the series named in the header does not exist");
  ExpectError(header("short.mhd", "4 3 4", "s%d.raw 0 2 1\n"), "truncated: header promises 96 data bytes, its 3 files hold 72");
  ExpectError(header("format.mhd", "4 3 3", "s%s%n.raw 0 2 1\n"), "with one %d in the pattern");
}

TEST(DataLoader, PlyFacesAreChecked)
{
  ExpectError(Bad + "face-index-out-of-range.ply", "face 0 refers to vertex 99999999 of 3");
  ExpectError(Bad + "short-face-line.ply", "face 0 lists 200 'vertex_indices' but fewer are there");
  // Binary, big-endian: the second face names vertex 3 of 3.
  const std::string p = std::string(ART_TEST_OUTPUT) + "/face-index-binary.ply";
  {
    std::ofstream f(p, std::ios::binary);
    f << "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
    const unsigned char vertices[36] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x3f, 0x80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      0, 0, 0, 0, 0x3f, 0x80, 0, 0, 0, 0, 0, 0 };
    const unsigned char faces[26] = { 3, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2, 3, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 3 };
    f.write(reinterpret_cast<const char*>(vertices), sizeof vertices);
    f.write(reinterpret_cast<const char*>(faces), sizeof faces);
  }
  ExpectError(p, "face 1 refers to vertex 3 of 3");
  // The same file with a valid index loads.
  {
    std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-1, std::ios::end);
    f.put(2);
  }
  EXPECT_EQ(art::LoadSurface(p)->GetNumberOfPolys(), 2);
}

// vtkNrrdReader (VTK 9.1) never returned on a detached header whose last line has no line end (a
// .nhdr saved without a final newline), nor on attached data with no blank line before it.
TEST(DataLoader, NrrdHeaderWithoutEnd)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  const std::string header = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nencoding: raw\nendian: little\n";
  std::ofstream(dir + "end.raw", std::ios::binary) << std::string(48, 'x');
  std::ofstream(dir + "no-newline.nhdr", std::ios::binary) << header << "data file: end.raw";
  ExpectError(dir + "no-newline.nhdr", "the header's last line has no line end");
  std::ofstream(dir + "newline.nhdr", std::ios::binary) << header << "data file: end.raw\n";
  EXPECT_EQ(art::LoadVolume(dir + "newline.nhdr")->GetNumberOfPoints(), 24);
  std::ofstream(dir + "no-blank.nrrd", std::ios::binary) << header << std::string(48, 'x');
  ExpectError(dir + "no-blank.nrrd", "the header has no blank line before its data");
}

// A 4-D NRRD whose first axis is in space (a time series) came out as a volume one axis short,
// the time steps as its components; a first axis of vectors (diffusion data) stays the components.
TEST(DataLoader, NrrdFourAxes)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  auto write = [&dir](const std::string& name, const std::string& sizes, const std::string& fields) {
    std::ofstream(dir + name, std::ios::binary) << "NRRD0004\ntype: uchar\ndimension: 4\nsizes: " << sizes << "\n"
                                                << fields << "encoding: raw\n\n" << std::string(120, 'x');
    return dir + name;
  };
  ExpectError(write("time.nrrd", "5 4 3 2", "kinds: domain domain domain list\n"),
    "a 4-D image whose first axis is in space (sizes 5 4 3 2, kinds domain domain domain list): only 3-D volumes are read");
  ExpectError(write("time-dirs.nrrd", "5 4 3 2", "space: LPS\nspace directions: (1,0,0) (0,1,0) (0,0,1) none\n"),
    "a 4-D image whose first axis is in space");
  auto img = art::LoadVolume(write("vectors.nrrd", "2 5 4 3", "kinds: vector domain domain domain\n"));
  EXPECT_EQ(img->GetPointData()->GetScalars()->GetNumberOfComponents(), 2);
  EXPECT_EQ(img->GetNumberOfPoints(), 60);
}

// vtkNrrdReader reported raw data shorter than the header's sizes as "File operation failed:
// 18446744073709305856, ext: ..."; the size is checked first, for attached and detached data.
TEST(DataLoader, TruncatedNrrd)
{
  const std::string dir = std::string(ART_TEST_OUTPUT) + "/";
  const std::string header = "NRRD0004\ntype: short\ndimension: 3\nsizes: 11 5 3\nencoding: raw\nendian: little\n";
  std::ofstream(dir + "short.nrrd", std::ios::binary) << header << "\n" << std::string(100, 'x');
  ExpectError(dir + "short.nrrd", "truncated: header promises 330 data bytes, file holds 100");
  std::ofstream(dir + "short.raw", std::ios::binary) << std::string(329, 'x');
  std::ofstream(dir + "short.nhdr", std::ios::binary) << header << "data file: short.raw\n";
  ExpectError(dir + "short.nhdr", "truncated: header promises 330 data bytes, file holds 329");
  std::ofstream(dir + "short.raw", std::ios::binary) << std::string(330, 'x');
  EXPECT_EQ(art::LoadVolume(dir + "short.nhdr")->GetNumberOfPoints(), 165);
  // vtkNrrdReader segfaulted on every data file series, complete or not, raw or gzip.
  for (const std::string series : { "LIST\nshort.raw\nshort.raw\nshort.raw", "short%d.raw 0 2 1" })
  {
    std::ofstream(dir + "series.nhdr", std::ios::binary) << header << "data file: " << series << "\n";
    ExpectError(dir + "series.nhdr", "is a series of files, which VTK's NRRD reader cannot read");
  }
  // A data file whose name has a space or two, or a '%', is one file (as NRRD and VTK read it); it
  // was refused as a series. Three spaces or more VTK takes for a series's pattern: said so.
  for (const std::string name : { "my short.raw", "my short %.raw", "a b c.raw" })
  {
    std::ofstream(dir + name, std::ios::binary) << std::string(330, 'x');
    std::ofstream(dir + "spaced.nhdr", std::ios::binary) << header << "data file: " << name << "\n";
    EXPECT_EQ(art::LoadVolume(dir + "spaced.nhdr")->GetNumberOfPoints(), 165) << name;
  }
  std::ofstream(dir + "spaced.nhdr", std::ios::binary) << header << "data file: a b c d.raw\n";
  ExpectError(dir + "spaced.nhdr", "has three spaces or more in its name, which VTK's NRRD reader takes for a series");
}

// The same choice on a mesh (the viewer's --array; render's for meshes needs it too): the vector's
// magnitude or component joins its data beside it, under the name to look up.
TEST(DataLoader, MeshVectorMagnitudeOrComponent)
{
  const std::string path = std::string(ART_SOURCE_DIR) + "/tests/data/vectors/velocity-box.vtu";
  auto grid = art::LoadMesh(path);
  EXPECT_EQ(art::AddComponentArray(grid, "velocity", path), "velocity");
  EXPECT_EQ(art::AddComponentArray(grid, "velocity:Magnitude", path), "velocity:magnitude");
  EXPECT_EQ(art::AddComponentArray(grid, "velocity:z", path), "velocity:2");
  EXPECT_EQ(art::AddComponentArray(grid, "region:0", path), "region:0");
  vtkDataArray* v = grid->GetPointData()->GetArray("velocity");
  vtkDataArray* m = grid->GetPointData()->GetArray("velocity:magnitude");
  vtkDataArray* z = grid->GetPointData()->GetArray("velocity:2");
  ASSERT_TRUE(v && m && z);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    const double* t = v->GetTuple3(i);
    EXPECT_DOUBLE_EQ(m->GetTuple1(i), std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
    EXPECT_EQ(z->GetTuple1(i), t[2]);
  }
  EXPECT_TRUE(grid->GetCellData()->GetArray("region:0")); // a cell array's stays with the cells
  try
  {
    art::AddComponentArray(grid, "speed:magnitude", path);
    ADD_FAILURE() << "no error";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("velocity-box.vtu: has no point or cell array 'speed' (it has: velocity"),
      std::string::npos)
      << e.what();
  }
}
