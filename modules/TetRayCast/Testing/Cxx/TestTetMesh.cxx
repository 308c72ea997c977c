// art::TetMesh from VTK data: what a bad or unusual mesh or image is told (missing scalars,
// surface cells, duplicate, unused or non-finite points, memory guards), and what it keeps.
#include "Error.h"
#include "MeshFixtures.h"
#include "TetRayCaster.h"

#include <gtest/gtest.h>
#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <limits>

using namespace art;
using fixtures::Linear;
using fixtures::LinearTF;
using fixtures::ViewOf;

TEST(TetMesh, FromImageSaysWhatIsMissing)
{
  // A 10 x 10 x 1 image has scalars but no cells: the message says that, not "needs scalars".
  vtkNew<vtkImageData> flat;
  flat->SetDimensions(10, 10, 1);
  flat->AllocateScalars(VTK_FLOAT, 1);
  try
  {
    TetMesh::FromImage(flat, "flat.vti");
    FAIL() << "a one-voxel-thick image was accepted";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("10 x 10 x 1 voxels has no cells"), std::string::npos) << what;
    EXPECT_EQ(what.find("scalars"), std::string::npos) << what;
  }
  vtkNew<vtkImageData> bare;
  bare->SetDimensions(4, 4, 4);
  EXPECT_THROW(TetMesh::FromImage(bare), Error);
  // Scalars of another image's size (set by hand) were read past their end.
  vtkNew<vtkFloatArray> few;
  few->SetNumberOfTuples(27);
  few->Fill(1.0);
  bare->GetPointData()->SetScalars(few);
  try
  {
    TetMesh::FromImage(bare, "few.vti");
    FAIL() << "27 values for 64 voxels accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("few.vti: the volume's scalars hold 27 values for 4 x 4 x 4 voxels"),
      std::string::npos) << e.what();
  }
  // NaN voxels (a masked MRI map) are named as voxels, by their index in the extent; the message
  // was the mesh's "point 21 has a non-finite coordinate or scalar".
  vtkNew<vtkImageData> masked;
  masked->SetExtent(10, 13, 0, 3, 5, 8);
  masked->AllocateScalars(VTK_FLOAT, 1);
  masked->GetPointData()->GetScalars()->Fill(1.0);
  masked->GetPointData()->GetScalars()->SetComponent(1 + 4 * (1 + 4 * 1), 0, std::nan(""));
  masked->GetPointData()->GetScalars()->SetComponent(63, 0, std::numeric_limits<double>::infinity());
  try
  {
    TetMesh::FromImage(masked, "masked.vti");
    FAIL() << "NaN voxels were accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("2 voxels hold NaN or infinite values (the first at i, j, k = 11, 1, 6)"),
      std::string::npos)
      << e.what();
  }
}

TEST(TetMesh, FromVTKAndBadMeshes)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  pts->InsertNextPoint(0, 0, 1);
  pts->InsertNextPoint(1, 1, 1);
  pts->InsertNextPoint(-1, -1, 0.5);
  ug->SetPoints(pts);
  vtkIdType t0[4] = { 0, 1, 2, 3 }, t1[4] = { 1, 2, 3, 4 };
  ug->InsertNextCell(VTK_TETRA, 4, t0);
  ug->InsertNextCell(VTK_TETRA, 4, t1);
  EXPECT_THROW(TetMesh::FromVTK(ug), Error); // no scalars at all
  // Cell scalars only: averaged to the points (as vtkCellDataToPointData does), with a note.
  vtkNew<vtkDoubleArray> cs;
  cs->SetName("pressure");
  cs->InsertNextValue(2.0);
  cs->InsertNextValue(6.0);
  ug->GetCellData()->SetScalars(cs);
  std::string cellNote;
  const TetMesh cm = TetMesh::FromVTK(ug, {}, &cellNote);
  EXPECT_NE(cellNote.find("cell scalars 'pressure' were averaged to the points"), std::string::npos) << cellNote;
  EXPECT_DOUBLE_EQ(cm.Scalars()[0], 2.0); // only in tet 0
  EXPECT_DOUBLE_EQ(cm.Scalars()[4], 6.0); // only in tet 1
  EXPECT_DOUBLE_EQ(cm.Scalars()[1], 4.0); // shared
  EXPECT_THROW(TetMesh::FromVTK(ug, "temperature"), Error);
  // An array shorter than its cells or points (made by hand) was read past its end ('point 31 has a
  // non-finite coordinate or scalar', or a crash): it is named with both counts.
  cs->SetNumberOfTuples(1);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "short.vtu");
    FAIL() << "a short cell array accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("short.vtu: cell array 'pressure' holds 1 values for 2 cells"),
      std::string::npos) << e.what();
  }
  ug->GetCellData()->Initialize();
  vtkNew<vtkDoubleArray> s;
  s->SetName("f");
  for (int i = 0; i < 3; ++i)
    s->InsertNextValue(i);
  ug->GetPointData()->SetScalars(s);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "short.vtu");
    FAIL() << "a short point array accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("short.vtu: point array 'f' holds 3 values for 6 points"),
      std::string::npos) << e.what();
  }
  for (int i = 3; i < 6; ++i)
    s->InsertNextValue(i);
  const TetMesh m = TetMesh::FromVTK(ug);
  EXPECT_EQ(m.NumberOfTets(), 2u);
  EXPECT_EQ(m.Neighbours(0)[0], 1); // face (1,2,3) is shared
  EXPECT_EQ(m.BoundaryFaces().size(), 6u);
  // A third tet on the same face is inconsistent.
  vtkIdType t2[4] = { 1, 2, 3, 5 };
  ug->InsertNextCell(VTK_TETRA, 4, t2);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "three.vtu");
    FAIL();
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("three.vtu: inconsistent neighbours: a face of tet"), std::string::npos)
      << e.what();
    EXPECT_NE(std::string(e.what()).find("is shared by 3 tets"), std::string::npos) << e.what();
  }
  // Two tets on the same side of their shared face overlap.
  vtkNew<vtkUnstructuredGrid> over;
  vtkNew<vtkPoints> op;
  for (int i = 0; i < 4; ++i)
    op->InsertNextPoint(pts->GetPoint(i));
  op->InsertNextPoint(0.1, 0.1, 0.1); // inside tet (0, 1, 2, 3)
  over->SetPoints(op);
  vtkIdType inner[4] = { 1, 2, 3, 4 };
  over->InsertNextCell(VTK_TETRA, 4, t0);
  over->InsertNextCell(VTK_TETRA, 4, inner);
  vtkNew<vtkDoubleArray> os;
  for (int i = 0; i < 5; ++i)
    os->InsertNextValue(i);
  over->GetPointData()->SetScalars(os);
  try
  {
    TetMesh::FromVTK(over, {}, nullptr, "over.vtu");
    FAIL() << "overlapping tets accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("over.vtu: inconsistent neighbours: tets 0 and 1 lie on the same side"),
      std::string::npos) << e.what();
  }
  // A hexahedron is tetrahedralised with a note.
  vtkNew<vtkUnstructuredGrid> hex;
  vtkNew<vtkPoints> hp;
  vtkNew<vtkDoubleArray> hs;
  for (int i = 0; i < 8; ++i)
  {
    hp->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    hs->InsertNextValue(i);
  }
  hex->SetPoints(hp);
  hex->GetPointData()->SetScalars(hs);
  vtkIdType h[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  hex->InsertNextCell(VTK_HEXAHEDRON, 8, h);
  std::string note;
  const TetMesh hm = TetMesh::FromVTK(hex, {}, &note);
  EXPECT_GE(hm.NumberOfTets(), 5u);
  EXPECT_NE(note.find("tetrahedralised"), std::string::npos);
}

// A mesh whose tets each keep their own points (as exported meshes often do) is merged back into
// one with shared faces, with a note: the same tets and boundary, and the same image as the shared
// mesh. Points equal in position but not in scalar (a discontinuous field) are kept apart.
TEST(TetMesh, DuplicatePointsAreMerged)
{
  const TetMesh shared = fixtures::GridMesh(3, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (std::size_t t = 0; t < shared.NumberOfTets(); ++t)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      const Vec3& p = shared.PointsArray()[shared.Tet(t)[k]];
      ids[k] = pts->InsertNextPoint(p.x, p.y, p.z);
      f->InsertNextValue(shared.Scalars()[shared.Tet(t)[k]]);
    }
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find(std::to_string(4 * shared.NumberOfTets() - shared.PointsArray().size()) + " duplicate points"),
    std::string::npos) << note;
  EXPECT_EQ(m.PointsArray().size(), shared.PointsArray().size());
  EXPECT_EQ(m.BoundaryFaces().size(), shared.BoundaryFaces().size());
  // A preset's unit distance counts the merged points, as for the mesh with shared points.
  const double spacing = std::cbrt(3.0 * 2.0 * 2.0 / double(shared.PointsArray().size()));
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug, &m), spacing, 1e-12);
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug), std::cbrt(12.0 / double(4 * shared.NumberOfTets())), 1e-12)
    << "without the mesh, every cell's own points";
  // Points no cell uses (far away) change neither the mesh's bounds nor its count.
  for (int k = 0; k < 5; ++k)
  {
    pts->InsertNextPoint(100.0 + k, 0, 0);
    f->InsertNextValue(0.0);
  }
  const TetMesh withUnused = TetMesh::FromVTK(ug, {}, nullptr);
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug, &withUnused), spacing, 1e-12);
  EXPECT_TRUE(m.IsConvex());
  RenderSettings s;
  s.tf = LinearTF(shared.ScalarRange(0), shared.ScalarRange(1));
  const Camera cam = ViewOf(shared.Bounds(), 24, 20, 35, 25);
  Image a, b;
  TetRayCaster(shared, s).Render(cam, a);
  TetRayCaster(m, s).Render(cam, b);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 24; ++x)
      ASSERT_NEAR(a.Pixel(x, y)[3], b.Pixel(x, y)[3], 1e-12) << x << "," << y;
  // A jump in the field across every face: nothing merges.
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
  {
    f->SetValue(i, f->GetValue(i) + 0.01 * (i / 4)); // a different offset in every tet
  }
  f->Modified();
  note.clear();
  const TetMesh apart = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(note.find("duplicate"), std::string::npos) << note;
  EXPECT_EQ(apart.BoundaryFaces().size(), 4 * apart.NumberOfTets());
}

// A surface saved as a grid is named as such; surface cells beside tets are left out with a note.
TEST(TetMesh, SurfaceCellsAreNamed)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  for (int i = 0; i < 5; ++i)
  {
    pts->InsertNextPoint(i == 1, i == 2, i == 3 ? 1 : (i == 4 ? -1 : 0));
    f->InsertNextValue(i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  vtkIdType tri[3] = { 0, 1, 2 }, tet[4] = { 0, 1, 2, 3 };
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "surface.vtu");
    ADD_FAILURE() << "a triangle-only grid was accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("holds no 3-D cells (its 1 cells are surface"), std::string::npos) << e.what();
  }
  ug->InsertNextCell(VTK_TETRA, 4, tet);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(m.NumberOfTets(), 1u);
  EXPECT_NE(note.find("1 cells that are not 3-D were left out"), std::string::npos) << note;
}

// Surface cells beside tets (as ParaView's output often has) are left out without tetrahedralising
// the tets again: the note does not claim a tetrahedralisation (it did, for every cell, and ran the
// triangle filter over the whole mesh: 2.4 s instead of 0.12 s for a 150k-tet mesh with one triangle).
// A hexahedron beside them is tetrahedralised and counted alone.
TEST(TetMesh, SurfaceCellsBesideTetsAreOnlyLeftOut)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(tets.Scalars()[i]);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  vtkIdType tri[3] = { 0, 1, 2 }, quad[4] = { 0, 1, 4, 3 };
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType ids[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->InsertNextCell(VTK_QUAD, 4, quad);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(note, "2 cells that are not 3-D were left out");
  ASSERT_EQ(m.NumberOfTets(), tets.NumberOfTets());
  for (std::size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    auto a = m.Tet(t), b = tets.Tet(t);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << t;
  }

  // A unit hexahedron apart from the grid (x 3 .. 4): 3-D, so tetrahedralised.
  const vtkIdType base = pts->GetNumberOfPoints();
  vtkIdType hex[8];
  for (int k = 0; k < 8; ++k)
  {
    const double x = 3 + ((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0), y = (k % 4 >= 2) ? 1 : 0, z = k >= 4;
    pts->InsertNextPoint(x, y, z);
    f->InsertNextValue(Linear(Vec3(x, y, z)));
    hex[k] = base + k;
  }
  ug->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  note.clear();
  const TetMesh withHex = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("non-tetrahedral cells were tetrahedralised (" + std::to_string(tets.NumberOfTets() + 1) +
              " 3-D cells -> "),
    std::string::npos)
    << note;
  EXPECT_NE(note.find("2 cells that are not 3-D were left out"), std::string::npos) << note;
  EXPECT_GT(withHex.NumberOfTets(), tets.NumberOfTets() + 4);
}

// A reducer's output (field data scalar_range_min/max, as ReducerVTK writes) maps presets onto its
// volume's range, as `render VOLUME --tets N` does: the fit's overshoot widened the mesh's own range,
// and a uint16 volume's mesh (0 .. 61481 reduced to -2132 .. 65580) took the CT preset in HU, 8.8 dB
// from the same tets rendered from the volume. Scalars a filter changed since keep their own range.
TEST(TetMesh, ReducedMeshKeepsItsVolumesRange)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f, twice;
  f->SetName("f");
  twice->SetName("twice");
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(1000 * tets.Scalars()[i]);
    twice->InsertNextValue(2000 * tets.Scalars()[i]);
  }
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType ids[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  ug->GetPointData()->AddArray(twice);
  double own[2];
  f->GetRange(own);
  const double lo = own[0] + 0.05 * (own[1] - own[0]), hi = own[1] - 0.05 * (own[1] - own[0]);
  auto field = [&](const char* name, double v) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(v);
    ug->GetFieldData()->AddArray(a);
  };
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(0), own[0]); // no field: its own
  field("scalar_range_min", lo);
  field("scalar_range_max", hi);
  const TetMesh reduced = TetMesh::FromVTK(ug);
  EXPECT_EQ(reduced.ScalarRange(0), lo);
  EXPECT_EQ(reduced.ScalarRange(1), hi);
  EXPECT_EQ(TetMesh::FromVTK(ug, "f").ScalarRange(1), hi); // the same array by name
  const TetMesh other = TetMesh::FromVTK(ug, "twice"); // another array: its own
  EXPECT_EQ(other.ScalarRange(1), 2 * own[1]);
  ug->GetPointData()->SetScalars(twice); // rescaled since (a calculator): its own range
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(1), 2 * own[1]);
}

// Without active scalars (as ParaView saves a filter's output), the field is the first array that
// is not VTK's bookkeeping: ParaView's Extract Selection puts vtkOriginalPointIds first, and the
// point ids were rendered as the field without a word.
TEST(TetMesh, BookkeepingArraysAreNotTheField)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> ids, f;
  ids->SetName("vtkOriginalPointIds");
  f->SetName("density");
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    ids->InsertNextValue(static_cast<double>(i));
    f->InsertNextValue(tets.Scalars()[i]);
  }
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType c[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, c);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->AddArray(ids);
  ug->GetPointData()->AddArray(f);
  ASSERT_EQ(ug->GetPointData()->GetScalars(), nullptr);
  const TetMesh m = TetMesh::FromVTK(ug);
  for (std::size_t i = 0; i < m.NumberOfPoints(); ++i)
  {
    EXPECT_EQ(m.Scalars()[i], tets.Scalars()[i]) << i;
  }
  ug->GetPointData()->RemoveArray("density"); // only bookkeeping left: taken as before
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(1), double(tets.NumberOfPoints() - 1));
}

// Points no tet uses (a clip's leftovers, stray points far away, a NaN among them) are dropped:
// the bounds, and so the framing, are the tets', and the mesh is not refused.
TEST(TetMesh, UnusedPointsAreDropped)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  auto stray = [&](double x, double v) {
    pts->InsertNextPoint(x, x, x);
    f->InsertNextValue(v);
  };
  stray(1000, 1);
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(tets.Scalars()[i]);
    if (i == 5)
    {
      stray(std::nan(""), std::nan(""));
    }
  }
  stray(-1e9, 0);
  auto id = [](std::size_t i) { return static_cast<vtkIdType>(1 + i + (i > 5 ? 1 : 0)); };
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
      ids[k] = id(tets.Tet(t)[k]);
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("3 points no tet uses were dropped"), std::string::npos) << note;
  EXPECT_EQ(m.NumberOfPoints(), tets.NumberOfPoints());
  EXPECT_EQ(m.Bounds().lo.x, 0.0);
  EXPECT_EQ(m.Bounds().hi.x, 2.0);
  for (std::size_t i = 0; i < m.NumberOfPoints(); ++i)
    EXPECT_EQ(m.Scalars()[i], tets.Scalars()[i]) << i; // in order
}

// Cell scalars of hexahedra are averaged to the points on the hexahedra, as vtkCellDataToPointData
// gives them, not on the tets they are split into (which would weigh a cell by its tet count).
TEST(TetMesh, CellScalarsAveragedBeforeTetrahedralising)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        pts->InsertNextPoint(i, j, k);
  ug->SetPoints(pts);
  auto id = [](int i, int j, int k) { return vtkIdType(i + 3 * (j + 2 * k)); };
  for (int c = 0; c < 2; ++c)
  {
    const vtkIdType h[8] = { id(c, 0, 0), id(c + 1, 0, 0), id(c + 1, 1, 0), id(c, 1, 0), id(c, 0, 1), id(c + 1, 0, 1),
      id(c + 1, 1, 1), id(c, 1, 1) };
    ug->InsertNextCell(VTK_HEXAHEDRON, 8, h);
  }
  vtkNew<vtkDoubleArray> v;
  v->SetName("phase");
  v->InsertNextValue(0.0);
  v->InsertNextValue(1.0);
  ug->GetCellData()->SetScalars(v);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("tetrahedralised"), std::string::npos) << note;
  EXPECT_NE(note.find("cell scalars 'phase' were averaged"), std::string::npos) << note;
  int middle = 0;
  for (std::size_t p = 0; p < m.PointsArray().size(); ++p)
  {
    const double x = m.PointsArray()[p].x;
    EXPECT_DOUBLE_EQ(m.Scalars()[p], x == 0 ? 0.0 : (x == 1 ? 0.5 : 1.0)) << "point at x = " << x;
    middle += x == 1 ? 1 : 0;
  }
  EXPECT_EQ(middle, 4);
}

// Full-resolution tets that would not fit are refused before anything is built, naming the file
// and the memory (the CT head's 4.3 M tets need about 0.7 GB).
TEST(TetMesh, FullResolutionMemoryGuard)
{
  const long long ctHead = 5LL * 127 * 127 * 53;
  EXPECT_NO_THROW(TetMesh::CheckFullResolutionFits(ctHead, 24e9, "head.mha"));
  EXPECT_NO_THROW(TetMesh::CheckFullResolutionFits(ctHead, 0.0, "head.mha")); // memory unknown
  try
  {
    TetMesh::CheckFullResolutionFits(ctHead, 0.5e9, "head.mha");
    FAIL() << "0.7 GB of tets accepted with 0.5 GB available";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("head.mha"), std::string::npos) << what;
    EXPECT_NE(what.find("need about 0.684 GB, more than the 0.5 GB of memory available"), std::string::npos) << what;
    EXPECT_NE(what.find("--tets"), std::string::npos) << what;
  }
  EXPECT_THROW(TetMesh::CheckFullResolutionFits(1LL << 29, 0.0, "big.mha"), Error);
}

// A flat tet (four coplanar points, as Delaunay meshes of lattice points have) has no side of its
// faces: it is linked to its neighbour, not reported as an overlap.
TEST(TetMesh, FlatTetBesideANormalOneIsLinked)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 } };
  vtkNew<vtkDoubleArray> s;
  for (int i = 0; i < 5; ++i)
  {
    pts->InsertNextPoint(p[i]);
    s->InsertNextValue(i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(s);
  vtkIdType normal[4] = { 0, 1, 2, 3 }, flat[4] = { 0, 1, 2, 4 };
  ug->InsertNextCell(VTK_TETRA, 4, normal);
  ug->InsertNextCell(VTK_TETRA, 4, flat);
  const TetMesh m = TetMesh::FromVTK(ug, {}, nullptr, "flat.vtu");
  EXPECT_EQ(m.BoundaryFaces().size(), 6u); // 8 faces, one pair shared
}

// Full-resolution tets of denormal voxels (1e-310) are refused with the way out: the transfer
// function built over their range crashed (its table's scale, the range's inverse, was inf).
TEST(TetMesh, DenormalVoxelsAreRefused)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(3, 3, 3);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(27);
  for (int i = 0; i < 27; ++i)
  {
    s->SetValue(i, 1e-310 * (1 + i));
  }
  img->GetPointData()->SetScalars(s);
  try
  {
    TetMesh::FromImage(img, "tiny.vti");
    FAIL() << "denormal voxels accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("tiny.vti: the scalars' range 1e-310 .. 2.7e-309 lies below 1e-150"),
      std::string::npos)
      << e.what();
  }
}

// A mesh's NaN point scalars (a masked simulation field) are counted and the first placed in the
// world, with what to do; it said 'point 2 has a non-finite coordinate or scalar', an index into
// the mesh as cleaned (unused points dropped, duplicates merged), not the file's.
TEST(TetMesh, NaNPointScalarsAreCountedAndPlaced)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  const double p[6][3] = { { 9, 9, 9 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  vtkNew<vtkDoubleArray> s;
  s->SetName("pressure");
  for (int i = 0; i < 6; ++i)
  {
    pts->InsertNextPoint(p[i]);
    s->InsertNextValue(i == 3 || i == 5 ? std::nan("") : i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(s);
  const vtkIdType a[4] = { 1, 2, 3, 4 }, b[4] = { 2, 3, 4, 5 };
  ug->InsertNextCell(VTK_TETRA, 4, a);
  ug->InsertNextCell(VTK_TETRA, 4, b);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "flow.vtu");
    FAIL() << "NaN scalars accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("flow.vtu: 2 points have a NaN or infinite scalar (the first at x, y, z = 0, "
                                         "1, 0); rendering needs finite values"),
      std::string::npos)
      << e.what();
  }
}

// A mesh whose tets would not fit in the memory available is refused before the triangle filter
// and the engine's arrays, naming the file, the tets and the way out.
TEST(TetMesh, MeshMemoryGuard)
{
  EXPECT_NO_THROW(TetMesh::CheckMeshFits(6000000, 24e9, "flow.vtu")); // 1.2 GB
  EXPECT_NO_THROW(TetMesh::CheckMeshFits(600000000, 0.0, "flow.vtu")); // memory unknown
  try
  {
    TetMesh::CheckMeshFits(150000000, 24e9, "flow.vtu"); // 25 million hexahedra: 30 GB
    FAIL() << "30 GB of tets accepted with 24 GB available";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()), "flow.vtu: its cells make about 150000000 tets, which need about 30 GB, more than "
                                     "the 24 GB of memory available; render a part of it first (e.g. ParaView's "
                                     "Extract Cells By Region, Clip or Threshold)");
  }
}
