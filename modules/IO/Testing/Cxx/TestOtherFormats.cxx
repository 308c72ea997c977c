// Every reader OtherFormats adds, on a small file written here (by VTK's writer where it has one,
// by hand after the format's description where not), against VTK's own reader of that format:
// the same sizes, spacing and values (points and cells for meshes and surfaces).
#include "DataLoader.h"
#include "Error.h"

#include <vtkAVSucdReader.h>
#include <vtkBYUReader.h>
#include <vtkBYUWriter.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkExodusIIReader.h>
#include <vtkExodusIIWriter.h>
#include <vtkFacetReader.h>
#include <vtkFacetWriter.h>
#include <vtkFieldData.h>
#include <vtkGAMBITReader.h>
#include <vtkImageCast.h>
#include <vtkImageData.h>
#include <vtkImageReader.h>
#include <vtkIntArray.h>
#include <vtkJPEGReader.h>
#include <vtkJPEGWriter.h>
#include <vtkMINCImageReader.h>
#include <vtkMINCImageWriter.h>
#include <vtkMRCReader.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageReader.h>
#include <vtkMetaImageWriter.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSLCReader.h>
#include <vtkSphereSource.h>
#include <vtkTIFFReader.h>
#include <vtkTIFFWriter.h>
#include <vtkTecplotReader.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace
{
std::string Dir()
{
  const fs::path d = fs::path(ART_TEST_OUTPUT) / "TestOtherFormats";
  fs::create_directories(d);
  return d.string();
}

void Write(const std::string& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
}

template <class T>
std::string Bytes(const T& v)
{
  return std::string(reinterpret_cast<const char*>(&v), sizeof v);
}

// An 8 x 6 x 5 wavelet cast to `type`, values 0..255 (a round trip through 8-bit formats).
vtkSmartPointer<vtkImageData> Volume(int type = VTK_UNSIGNED_CHAR, int slices = 5)
{
  vtkNew<vtkRTAnalyticSource> src;
  src->SetWholeExtent(0, 7, 0, 5, 0, slices - 1);
  src->SetMaximum(255);
  vtkNew<vtkImageCast> cast;
  cast->SetInputConnection(src->GetOutputPort());
  cast->SetOutputScalarType(type);
  cast->ClampOverflowOn();
  cast->Update();
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->DeepCopy(cast->GetOutput());
  img->SetSpacing(0.5, 0.75, 2.0);
  return img;
}

// Our volume against VTK's reader's output: sizes, spacing, every value.
void ExpectSameImage(vtkImageData* ours, vtkImageData* vtk, bool spacing = true)
{
  int a[3], b[3];
  ours->GetDimensions(a);
  vtk->GetDimensions(b);
  for (int i = 0; i < 3; ++i)
  {
    ASSERT_EQ(a[i], b[i]) << "axis " << i;
    if (spacing)
    {
      EXPECT_NEAR(ours->GetSpacing()[i], vtk->GetSpacing()[i], 1e-6) << "axis " << i;
    }
  }
  vtkDataArray* s = ours->GetPointData()->GetScalars();
  vtkDataArray* t = vtk->GetPointData()->GetScalars();
  ASSERT_TRUE(s && t);
  ASSERT_EQ(s->GetNumberOfValues(), t->GetNumberOfValues());
  int differ = 0;
  for (vtkIdType i = 0; i < s->GetNumberOfValues(); ++i)
  {
    differ += s->GetVariantValue(i).ToDouble() != t->GetVariantValue(i).ToDouble();
  }
  EXPECT_EQ(differ, 0);
}

template <class Reader>
vtkSmartPointer<vtkImageData> VtkRead(const std::string& path)
{
  vtkNew<Reader> r;
  r->SetFileName(path.c_str());
  r->Update();
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->DeepCopy(r->GetOutputDataObject(0));
  return img;
}

// An SLC file of the volume: the header, a 1 x 1 icon (vtkSLCReader refuses an empty one), then
// slices plain (0) or run-length (1).
std::string Slc(vtkImageData* img, int compression)
{
  int d[3];
  img->GetDimensions(d);
  std::string s = "11111 " + std::to_string(d[0]) + " " + std::to_string(d[1]) + " " + std::to_string(d[2]) +
    " 8 0.5 0.75 2 0 0 0 " + std::to_string(compression) + "\n1 1 X" + std::string(3, '\0');
  const auto* v = static_cast<unsigned char*>(img->GetScalarPointer());
  const int plane = d[0] * d[1];
  for (int z = 0; z < d[2]; ++z)
  {
    const unsigned char* p = v + z * plane;
    if (compression == 0)
    {
      s.append(reinterpret_cast<const char*>(p), plane);
      continue;
    }
    std::string runs;
    for (int i = 0; i < plane; i += 100)
    {
      const int n = std::min(100, plane - i);
      runs += static_cast<char>(0x80 | n); // n literal bytes
      runs.append(reinterpret_cast<const char*>(p + i), n);
    }
    runs += '\0';
    s += std::to_string(runs.size()) + " X" + runs;
  }
  return s;
}
} // namespace

TEST(OtherFormats, Slc)
{
  auto img = Volume();
  for (int compression : { 0, 1 })
  {
    const std::string p = Dir() + "/wavelet" + std::to_string(compression) + ".slc";
    Write(p, Slc(img, compression));
    ExpectSameImage(art::LoadVolume(p), VtkRead<vtkSLCReader>(p));
    ExpectSameImage(art::LoadVolume(p), img);
  }
  // A run longer than the slice would overrun vtkSLCReader's buffer.
  std::string bad = Slc(img, 1);
  const std::size_t x = bad.find(" X", bad.find("1 1 X") + 8);
  bad[x + 2] = static_cast<char>(0x7F); // a repeat of 127 bytes
  Write(Dir() + "/overrun.slc", bad);
  EXPECT_THROW(art::LoadVolume(Dir() + "/overrun.slc"), art::Error);
}

TEST(OtherFormats, Minc)
{
  auto img = Volume(VTK_SHORT);
  const std::string p = Dir() + "/wavelet.mnc";
  vtkNew<vtkMINCImageWriter> w;
  w->SetInputData(img);
  w->SetFileName(p.c_str());
  w->Write();
  vtkNew<vtkMINCImageReader> r;
  r->SetFileName(p.c_str());
  r->RescaleRealValuesOn();
  r->Update();
  ExpectSameImage(art::LoadVolume(p), r->GetOutput());
}

TEST(OtherFormats, Mrc)
{
  auto img = Volume(VTK_FLOAT);
  char h[1024] = {};
  const std::int32_t n[4] = { 8, 6, 5, 2 }; // nx ny nz, mode 2 (float32)
  std::memcpy(h, n, sizeof n);
  const std::int32_t m[3] = { 8, 6, 5 };
  std::memcpy(h + 28, m, sizeof m);
  const float cell[3] = { 4.0f, 4.5f, 10.0f }; // spacing 0.5 0.75 2
  std::memcpy(h + 40, cell, sizeof cell);
  const std::int32_t axes[3] = { 1, 2, 3 };
  std::memcpy(h + 64, axes, sizeof axes);
  std::memcpy(h + 208, "MAP ", 4);
  h[212] = 0x44;
  h[213] = 0x41;
  const std::string p = Dir() + "/wavelet.mrc";
  Write(p, std::string(h, sizeof h) +
      std::string(static_cast<char*>(img->GetScalarPointer()), 8 * 6 * 5 * sizeof(float)));
  ExpectSameImage(art::LoadVolume(p), VtkRead<vtkMRCReader>(p));
  ExpectSameImage(art::LoadVolume(p), img, false);
  std::string cut = std::string(h, sizeof h) + std::string(100, '\0');
  Write(Dir() + "/cut.mrc", cut);
  EXPECT_THROW(art::LoadVolume(Dir() + "/cut.mrc"), art::Error);
}

TEST(OtherFormats, BioRadPic)
{
  // 76-byte header (nx, ny, npic, byte_format 1 = 8-bit, file_id 12345), voxels, one note.
  auto img = Volume();
  char h[76] = {};
  const std::uint16_t nx = 8, ny = 6, npic = 5;
  std::memcpy(h, &nx, 2);
  std::memcpy(h + 2, &ny, 2);
  std::memcpy(h + 4, &npic, 2);
  const std::int16_t one = 1, id = 12345;
  std::memcpy(h + 14, &one, 2);
  std::memcpy(h + 54, &id, 2);
  char note[96] = {};
  std::snprintf(note + 16, 80, "AXIS_4 001 0.000000e+00 2.000000e+00 microns");
  const std::string p = Dir() + "/wavelet.pic";
  Write(p, std::string(h, sizeof h) + std::string(static_cast<char*>(img->GetScalarPointer()), 8 * 6 * 5) +
      std::string(note, sizeof note));
  // VTK has no BioRad reader: its raw reader given the header's layout is the reference.
  vtkNew<vtkImageReader> r;
  r->SetFileName(p.c_str());
  r->SetHeaderSize(76);
  r->SetDataScalarTypeToUnsignedChar();
  r->SetFileDimensionality(3);
  r->SetDataExtent(0, 7, 0, 5, 0, 4);
  r->SetDataSpacing(1, 1, 2);
  r->FileLowerLeftOn();
  r->Update();
  ExpectSameImage(art::LoadVolume(p), r->GetOutput());
  ExpectSameImage(art::LoadVolume(p), img, false);
}

TEST(OtherFormats, AnalyzeHeaderAndImage)
{
  auto img = Volume(VTK_SHORT);
  const std::string p = Dir() + "/wavelet.hdr";
  vtkNew<vtkNIFTIImageWriter> w;
  w->SetInputData(img);
  w->SetFileName(p.c_str());
  w->Write();
  ASSERT_TRUE(fs::exists(Dir() + "/wavelet.img"));
  ExpectSameImage(art::LoadVolume(p), VtkRead<vtkNIFTIImageReader>(p));
  ExpectSameImage(art::LoadVolume(Dir() + "/wavelet.img"), img);
  fs::resize_file(Dir() + "/wavelet.img", 100);
  EXPECT_THROW(art::LoadVolume(p), art::Error);
}

TEST(OtherFormats, ThreeDimensionalTiffAndStacks)
{
  auto img = Volume();
  const std::string tif = Dir() + "/wavelet.tif";
  vtkNew<vtkTIFFWriter> w;
  w->SetInputData(img);
  w->SetFileName(tif.c_str());
  w->SetFileDimensionality(3);
  w->Write();
  vtkNew<vtkTIFFReader> r;
  r->SetFileName(tif.c_str());
  r->Update();
  ExpectSameImage(art::LoadVolume(tif), r->GetOutput(), false);
  ExpectSameImage(art::LoadVolume(tif), img, false);

  // PNG and JPEG slices, as a folder and as a pattern; spacing from --raw-spacing.
  for (const std::string kind : { "png", "jpg" })
  {
    const fs::path folder = fs::path(Dir()) / ("stack-" + kind);
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::string pattern = (folder / ("s%03d." + kind)).string();
    if (kind == "png")
    {
      vtkNew<vtkPNGWriter> pw;
      pw->SetInputData(img);
      pw->SetFilePattern(pattern.c_str());
      pw->Write();
    }
    else
    {
      vtkNew<vtkJPEGWriter> jw;
      jw->SetInputData(img);
      jw->SetFilePattern(pattern.c_str());
      jw->SetQuality(100);
      jw->Write();
    }
    art::LoadOptions o;
    o.Raw.SpacingGiven = true;
    o.Raw.Spacing[0] = 0.5, o.Raw.Spacing[1] = 0.75, o.Raw.Spacing[2] = 2;
    auto ours = art::LoadVolume(pattern, o);
    vtkSmartPointer<vtkImageReader2> vtk;
    if (kind == "png")
    {
      vtk = vtkSmartPointer<vtkPNGReader>::New();
    }
    else
    {
      vtk = vtkSmartPointer<vtkJPEGReader>::New();
    }
    vtk->SetFilePattern(pattern.c_str());
    vtk->SetDataExtent(0, 7, 0, 5, 0, 4);
    vtk->SetDataSpacing(0.5, 0.75, 2);
    vtk->Update();
    ExpectSameImage(ours, vtk->GetOutput());
    ExpectSameImage(art::LoadVolume(folder.string(), o), vtk->GetOutput());
    if (kind == "png")
    {
      ExpectSameImage(ours, img);
    }
  }
  EXPECT_THROW(art::LoadVolume(Dir() + "/stack-png/s000.png"), art::Error); // one 2-D slice
}

TEST(OtherFormats, RawVoxels)
{
  auto img = Volume(VTK_UNSIGNED_SHORT);
  const std::string p = Dir() + "/wavelet.raw";
  const std::string voxels(static_cast<char*>(img->GetScalarPointer()), 8 * 6 * 5 * 2);
  Write(p, std::string(32, 'h') + voxels);
  art::LoadOptions o;
  o.Raw.Dims[0] = 8, o.Raw.Dims[1] = 6, o.Raw.Dims[2] = 5;
  o.Raw.Type = "uint16";
  o.Raw.Spacing[0] = 0.5, o.Raw.Spacing[1] = 0.75, o.Raw.Spacing[2] = 2;
  vtkNew<vtkImageReader> r;
  r->SetFileName(p.c_str());
  r->SetDataScalarTypeToUnsignedShort();
  r->SetDataByteOrderToLittleEndian();
  r->SetFileDimensionality(3);
  r->SetDataExtent(0, 7, 0, 5, 0, 4);
  r->SetDataSpacing(0.5, 0.75, 2);
  r->FileLowerLeftOn();
  r->Update(); // no header size given: the voxels are the last bytes, as here
  ExpectSameImage(art::LoadVolume(p, o), r->GetOutput());
  ExpectSameImage(art::LoadVolume(p, o), img);
  o.Raw.HeaderBytes = 32;
  ExpectSameImage(art::LoadVolume(p, o), img);
  o.Raw.HeaderBytes = 16; // 16 bytes too many
  EXPECT_THROW(art::LoadVolume(p, o), art::Error);
  o.Raw.HeaderBytes = -1;
  o.Raw.Dims[2] = 50; // more voxels than the file holds
  EXPECT_THROW(art::LoadVolume(p, o), art::Error);
  EXPECT_THROW(art::LoadVolume(p), art::Error); // no layout
}

TEST(OtherFormats, FrameVtkIsWhatVtksReaderGives)
{
  // A MetaImage with a direction: patient frame turns it, vtk frame keeps VTK's reader's geometry.
  auto img = Volume(VTK_SHORT);
  img->SetOrigin(10, 20, 30);
  img->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1);
  const std::string p = Dir() + "/turned.mha";
  vtkNew<vtkMetaImageWriter> w;
  w->SetInputData(img);
  w->SetFileName(p.c_str());
  w->SetCompression(false);
  w->Write();
  std::ifstream in(p, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::size_t at = text.find("TransformMatrix");
  text.replace(at, text.find('\n', at) - at, "TransformMatrix = 0 1 0 -1 0 0 0 0 1");
  Write(p, text);
  art::LoadOptions vtkFrame;
  vtkFrame.Placement = art::Frame::Vtk;
  auto asVtk = art::LoadVolume(p, vtkFrame);
  auto vtk = VtkRead<vtkMetaImageReader>(p);
  ExpectSameImage(asVtk, vtk);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR(asVtk->GetOrigin()[a], vtk->GetOrigin()[a], 1e-9);
  }
  EXPECT_TRUE(asVtk->GetDirectionMatrix()->IsIdentity());
  auto patient = art::LoadVolume(p);
  EXPECT_FALSE(patient->GetDirectionMatrix()->IsIdentity());
  // The recorded matrix maps index (1, 0, 0) to the origin plus the first axis times its spacing.
  for (vtkImageData* v : { asVtk.GetPointer(), patient.GetPointer() })
  {
    auto* m = vtkDataArray::SafeDownCast(v->GetFieldData()->GetArray("IndexToWorld"));
    ASSERT_TRUE(m);
    double world[3];
    v->TransformIndexToPhysicalPoint(1, 0, 0, world);
    for (int r = 0; r < 3; ++r)
    {
      EXPECT_NEAR(m->GetComponent(0, 4 * r) + m->GetComponent(0, 4 * r + 3), world[r], 1e-9);
    }
  }
}

TEST(OtherFormats, ExodusII)
{
  vtkNew<vtkRTAnalyticSource> src;
  src->SetWholeExtent(0, 3, 0, 3, 0, 3);
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputConnection(src->GetOutputPort());
  tri->Update();
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  ug->DeepCopy(tri->GetOutput());
  vtkNew<vtkIntArray> ids, block;
  ids->SetName("GlobalElementId");
  block->SetName("ObjectId");
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
  {
    ids->InsertNextValue(static_cast<int>(c + 1));
    block->InsertNextValue(1);
  }
  ug->GetCellData()->AddArray(ids);
  ug->GetCellData()->AddArray(block);
  vtkNew<vtkIntArray> nodes;
  nodes->SetName("GlobalNodeId");
  for (vtkIdType p = 0; p < ug->GetNumberOfPoints(); ++p)
  {
    nodes->InsertNextValue(static_cast<int>(p + 1));
  }
  ug->GetPointData()->AddArray(nodes);
  const std::string p = Dir() + "/tets.exo";
  fs::remove(p);
  vtkNew<vtkExodusIIWriter> w;
  w->SetInputData(ug);
  w->SetFileName(p.c_str());
  w->WriteAllTimeStepsOff();
  w->Write();
  vtkNew<vtkExodusIIReader> r;
  r->SetFileName(p.c_str());
  r->UpdateInformation();
  r->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
  r->Update();
  vtkIdType cells = 0, points = 0;
  auto* mb = vtkMultiBlockDataSet::SafeDownCast(r->GetOutput());
  auto it = vtk::TakeSmartPointer(mb->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    cells += vtkDataSet::SafeDownCast(it->GetCurrentDataObject())->GetNumberOfCells();
    points += vtkDataSet::SafeDownCast(it->GetCurrentDataObject())->GetNumberOfPoints();
  }
  auto ours = art::LoadMesh(p);
  EXPECT_EQ(ours->GetNumberOfCells(), cells);
  EXPECT_EQ(ours->GetNumberOfCells(), ug->GetNumberOfCells());
  EXPECT_EQ(ours->GetNumberOfPoints(), points);
  EXPECT_TRUE(ours->GetPointData()->GetArray("RTData"));
}

TEST(OtherFormats, AvsUcdTecplotGambit)
{
  // One tetrahedron with a point value, in each text format.
  const std::string avs = Dir() + "/tet.inp";
  Write(avs, "# one tet\n4 1 1 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n1 1 tet 1 2 3 4\n1 1\nvalue, none\n"
             "1 10\n2 20\n3 30\n4 40\n");
  const std::string tec = Dir() + "/tet.tec";
  Write(tec, "TITLE = \"tet\"\nVARIABLES = \"X\", \"Y\", \"Z\", \"value\"\n"
             "ZONE N=4, E=1, DATAPACKING=POINT, ZONETYPE=FETETRAHEDRON\n"
             "0 0 0 10\n1 0 0 20\n0 1 0 30\n0 0 1 40\n1 2 3 4\n");
  const std::string neu = Dir() + "/tet.neu";
  Write(neu, "        CONTROL INFO 2.0.0\n** GAMBIT NEUTRAL FILE\ntet\nPROGRAM:                Gambit     VERSION:  2.0.0\n"
             "1 Jan 2000\n     NUMNP     NELEM     NGRPS    NBSETS     NDFCD     NDFVL\n"
             "         4         1         1         0         3         3\nENDOFSECTION\n"
             "   NODAL COORDINATES 2.0.0\n         1  0.0 0.0 0.0\n         2  1.0 0.0 0.0\n"
             "         3  0.0 1.0 0.0\n         4  0.0 0.0 1.0\nENDOFSECTION\n"
             "      ELEMENTS/CELLS 2.0.0\n       1  6  4        1       2       3       4\nENDOFSECTION\n"
             "       ELEMENT GROUP 2.0.0\nGROUP:          1 ELEMENTS:          1 MATERIAL:          2 NFLAGS:          1\n"
             "                           fluid\n       0\n       1\nENDOFSECTION\n");
  vtkNew<vtkAVSucdReader> a;
  a->SetFileName(avs.c_str());
  a->Update();
  vtkNew<vtkTecplotReader> t;
  t->SetFileName(tec.c_str());
  t->Update();
  vtkNew<vtkGAMBITReader> g;
  g->SetFileName(neu.c_str());
  g->Update();
  auto* tecBlock = vtkDataSet::SafeDownCast(vtkMultiBlockDataSet::SafeDownCast(t->GetOutput())->GetBlock(0));
  ASSERT_TRUE(tecBlock);
  const std::pair<std::string, vtkDataSet*> cases[] = { { avs, a->GetOutput() }, { tec, tecBlock },
    { neu, vtkDataSet::SafeDownCast(g->GetOutputDataObject(0)) } };
  for (const auto& [file, vtk] : cases)
  {
    auto ours = art::LoadMesh(file);
    ASSERT_EQ(ours->GetNumberOfCells(), 1) << file;
    EXPECT_EQ(ours->GetNumberOfCells(), vtk->GetNumberOfCells()) << file;
    EXPECT_EQ(ours->GetNumberOfPoints(), vtk->GetNumberOfPoints()) << file;
    EXPECT_EQ(ours->GetCellType(0), VTK_TETRA) << file;
    double b[6], c[6];
    ours->GetBounds(b);
    vtk->GetBounds(c);
    for (int i = 0; i < 6; ++i)
    {
      EXPECT_EQ(b[i], c[i]) << file;
    }
  }
  EXPECT_EQ(art::LoadMesh(avs)->GetPointData()->GetArray("value")->GetTuple1(3), 40.0);
  Write(Dir() + "/cut.inp", "4 1 1 0 0\n1 0 0 0\n");
  EXPECT_THROW(art::LoadMesh(Dir() + "/cut.inp"), art::Error);
}

TEST(OtherFormats, ByuAndFacetSurfaces)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  const std::string byu = Dir() + "/sphere.g", facet = Dir() + "/sphere.facet";
  vtkNew<vtkBYUWriter> bw;
  bw->SetInputData(sphere->GetOutput());
  bw->SetGeometryFileName(byu.c_str());
  bw->Write();
  vtkNew<vtkFacetWriter> fw;
  fw->SetInputData(sphere->GetOutput());
  fw->SetFileName(facet.c_str());
  fw->Write();
  vtkNew<vtkBYUReader> br;
  br->SetGeometryFileName(byu.c_str());
  br->Update();
  vtkNew<vtkFacetReader> fr;
  fr->SetFileName(facet.c_str());
  fr->Update();
  for (const auto& [file, vtk] : { std::pair<std::string, vtkPolyData*>{ byu, br->GetOutput() }, { facet, fr->GetOutput() } })
  {
    auto ours = art::LoadSurface(file);
    EXPECT_EQ(ours->GetNumberOfPolys(), sphere->GetOutput()->GetNumberOfPolys()) << file;
    EXPECT_EQ(ours->GetNumberOfPolys(), vtk->GetNumberOfPolys()) << file;
    EXPECT_EQ(ours->GetNumberOfPoints(), vtk->GetNumberOfPoints()) << file;
  }
}
