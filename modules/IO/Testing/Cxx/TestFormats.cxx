// Every volume, surface and grid format the loader claims is read back with the right geometry and
// values: files are written here with VTK's writers (or by hand for NRRD), then loaded.
#include "DataLoader.h"
#include "Error.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSetWriter.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkImageDataToPointSet.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageWriter.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkSTLWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkShortArray.h>
#include <vtkSphereSource.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLStructuredGridWriter.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace fs = std::filesystem;

namespace
{
std::string Dir()
{
  const fs::path d = fs::path(ART_TEST_OUTPUT) / "TestFormats";
  fs::create_directories(d);
  return d.string();
}

// An 11 x 5 x 3 int16 volume with distinct values, anisotropic spacing and an offset origin.
vtkSmartPointer<vtkImageData> SmallVolume()
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(11, 5, 3);
  img->SetSpacing(0.5, 0.75, 2.0);
  img->SetOrigin(10, -4, 3);
  vtkNew<vtkShortArray> s;
  s->SetName("scalars");
  s->SetNumberOfTuples(11 * 5 * 3);
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    s->SetValue(i, static_cast<short>(i * 37 - 1000));
  }
  img->GetPointData()->SetScalars(s);
  return img;
}

void ExpectSameVolume(vtkImageData* a, vtkImageData* b, bool checkOrigin = true)
{
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(da[i], db[i]);
    EXPECT_NEAR(a->GetSpacing()[i], b->GetSpacing()[i], 1e-6);
    if (checkOrigin)
    {
      EXPECT_NEAR(a->GetOrigin()[i], b->GetOrigin()[i], 1e-6);
    }
  }
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  ASSERT_EQ(sa->GetNumberOfTuples(), sb->GetNumberOfTuples());
  for (vtkIdType i = 0; i < sa->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(sa->GetTuple1(i), sb->GetTuple1(i)) << "voxel " << i;
  }
}

template <class Writer>
bool WriteSurface(vtkPolyData* pd, const std::string& path)
{
  vtkNew<Writer> w;
  w->SetInputData(pd);
  w->SetFileName(path.c_str());
  return w->Write() == 1;
}

template <class Writer>
void WriteVolume(vtkDataObject* img, const std::string& path)
{
  vtkNew<Writer> w;
  w->SetInputData(img);
  w->SetFileName(path.c_str());
  w->Write();
}
}

TEST(Formats, MetaImageVtiNifti)
{
  auto img = SmallVolume();
  WriteVolume<vtkMetaImageWriter>(img, Dir() + "/v.mha");
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/v.mha"));
  WriteVolume<vtkXMLImageDataWriter>(img, Dir() + "/v.vti");
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/v.vti"));
  // NIfTI keeps the origin in its qform, which VTK's reader does not put into the origin.
  WriteVolume<vtkNIFTIImageWriter>(img, Dir() + "/v.nii");
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/v.nii"), false);
  WriteVolume<vtkNIFTIImageWriter>(img, Dir() + "/v.nii.gz");
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/v.nii.gz"), false);
}

// NIfTI's scl_slope / scl_inter are applied (a CT stored as uint16 with intercept -1024 loads in
// Hounsfield units), as the file says the values are; a NaN slope means none.
TEST(Formats, NiftiRescaleSlopeAndIntercept)
{
  auto img = SmallVolume();
  vtkNew<vtkNIFTIImageWriter> w;
  w->SetInputData(img);
  w->SetFileName((Dir() + "/scaled.nii").c_str());
  w->SetRescaleSlope(2.0);
  w->SetRescaleIntercept(-1024.0);
  w->Write();
  auto back = art::LoadVolume(Dir() + "/scaled.nii");
  vtkDataArray* a = img->GetPointData()->GetScalars();
  vtkDataArray* b = back->GetPointData()->GetScalars();
  ASSERT_EQ(a->GetNumberOfTuples(), b->GetNumberOfTuples());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(b->GetTuple1(i), 2.0 * a->GetTuple1(i) - 1024.0) << "voxel " << i;
  }
  // A NaN scl_slope (header bytes 112-115) means no scaling, as nifti1_io reads it.
  std::fstream f(Dir() + "/scaled.nii", std::ios::in | std::ios::out | std::ios::binary);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  f.seekp(112);
  f.write(reinterpret_cast<const char*>(&nan), sizeof nan);
  f.close();
  auto unscaled = art::LoadVolume(Dir() + "/scaled.nii");
  vtkDataArray* c = unscaled->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(c->GetTuple1(i), a->GetTuple1(i)) << "voxel " << i;
  }
}

// A 4 x 3 x 2 int16 NIfTI-1 file written byte by byte, so its qform and sform are exactly what a
// test says; voxel (i, j, k) of the file holds i + 10 j + 100 k.
struct NiftiHeader
{
  float pixdim[4] = { 1, 2, 3, 4 }; // pixdim[0] is qfac
  short qformCode = 0, sformCode = 0;
  float quatern[3] = { 0, 0, 0 }, qoffset[3] = { 0, 0, 0 };
  float srow[12] = { 0 };
};

void WriteNifti(const std::string& path, const NiftiHeader& h)
{
  char b[352] = {};
  auto put = [&b](int at, const void* v, int n) { std::memcpy(b + at, v, n); };
  const int size = 348;
  put(0, &size, 4);
  const short dim[8] = { 3, 4, 3, 2, 1, 1, 1, 1 };
  put(40, dim, 16);
  const short datatype = 4, bitpix = 16; // int16
  put(70, &datatype, 2);
  put(72, &bitpix, 2);
  put(76, h.pixdim, 16);
  const float voxOffset = 352;
  put(108, &voxOffset, 4);
  b[123] = 2; // millimetres
  put(252, &h.qformCode, 2);
  put(254, &h.sformCode, 2);
  put(256, h.quatern, 12);
  put(268, h.qoffset, 12);
  put(280, h.srow, 48);
  put(344, "n+1", 4);
  std::ofstream f(path, std::ios::binary);
  f.write(b, sizeof b);
  for (short k = 0; k < 2; ++k)
    for (short j = 0; j < 3; ++j)
      for (short i = 0; i < 4; ++i)
      {
        const short v = i + 10 * j + 100 * k;
        f.write(reinterpret_cast<const char*>(&v), 2);
      }
}

// Every loaded voxel lies where `ras` puts the file's voxel (i, j, k) it holds, in LPS: (-x, -y, z).
template <class Ras>
void ExpectPlacedAt(const std::string& path, Ras ras)
{
  auto img = art::LoadVolume(path);
  int d[3];
  img->GetDimensions(d);
  ASSERT_EQ(d[0] * d[1] * d[2], 24) << path;
  const int* e = img->GetExtent();
  vtkDataArray* s = img->GetPointData()->GetScalars();
  for (int K = 0; K < d[2]; ++K)
    for (int J = 0; J < d[1]; ++J)
      for (int I = 0; I < d[0]; ++I)
      {
        const int v = static_cast<int>(s->GetTuple1(I + d[0] * (J + d[1] * K)));
        const std::array<double, 3> want = ras(v % 10, v / 10 % 10, v / 100);
        double x[3];
        img->TransformContinuousIndexToPhysicalPoint(e[0] + I, e[2] + J, e[4] + K, x);
        EXPECT_NEAR(x[0], -want[0], 1e-5) << path << " voxel " << v;
        EXPECT_NEAR(x[1], -want[1], 1e-5) << path << " voxel " << v;
        EXPECT_NEAR(x[2], want[2], 1e-5) << path << " voxel " << v;
      }
}

// vtkNIFTIImageReader leaves qform and sform to the caller: a radiological file (x flipped)
// rendered mirrored. The sform (else the qform) now places the voxels, as nibabel chooses, in the
// LPS world of DICOM and ITK's MetaImage (NIfTI's RAS with x and y negated).
TEST(Formats, NiftiQformAndSformPlaceTheVoxels)
{
  NiftiHeader radiological; // sform only, x flipped
  radiological.sformCode = 2;
  const float srow[12] = { -2, 0, 0, 10, 0, 3, 0, 20, 0, 0, 4, 30 };
  std::copy(srow, srow + 12, radiological.srow);
  WriteNifti(Dir() + "/sform.nii", radiological);
  ExpectPlacedAt(Dir() + "/sform.nii", [](int i, int j, int k) {
    return std::array<double, 3>{ 10.0 - 2 * i, 20.0 + 3 * j, 30.0 + 4 * k };
  });
  // The sform's scale wins over pixdim.
  NiftiHeader scaled = radiological;
  std::fill(scaled.pixdim, scaled.pixdim + 4, 1.0f);
  WriteNifti(Dir() + "/sform-scaled.nii", scaled);
  ExpectPlacedAt(Dir() + "/sform-scaled.nii", [](int i, int j, int k) {
    return std::array<double, 3>{ 10.0 - 2 * i, 20.0 + 3 * j, 30.0 + 4 * k };
  });

  NiftiHeader qfac; // qform only, slices reversed by qfac = -1 (VTK reorders them)
  qfac.qformCode = 1;
  qfac.pixdim[0] = -1;
  const float offset[3] = { 10, 20, 30 };
  std::copy(offset, offset + 3, qfac.qoffset);
  WriteNifti(Dir() + "/qfac.nii", qfac);
  ExpectPlacedAt(Dir() + "/qfac.nii", [](int i, int j, int k) {
    return std::array<double, 3>{ 10.0 + 2 * i, 20.0 + 3 * j, 30.0 - 4 * k };
  });

  NiftiHeader turned; // qform turned 90 degrees about z
  turned.qformCode = 1;
  turned.quatern[2] = static_cast<float>(std::sqrt(0.5));
  const float offset2[3] = { 1, 2, 3 };
  std::copy(offset2, offset2 + 3, turned.qoffset);
  WriteNifti(Dir() + "/qform.nii", turned);
  const auto turnedRas = [](int i, int j, int k) { return std::array<double, 3>{ 1.0 - 3 * j, 2.0 + 2 * i, 3.0 + 4 * k }; };
  ExpectPlacedAt(Dir() + "/qform.nii", turnedRas);

  NiftiHeader both = turned; // the sform wins
  both.sformCode = 1;
  std::copy(srow, srow + 12, both.srow);
  WriteNifti(Dir() + "/both.nii", both);
  ExpectPlacedAt(Dir() + "/both.nii", [](int i, int j, int k) {
    return std::array<double, 3>{ 10.0 - 2 * i, 20.0 + 3 * j, 30.0 + 4 * k };
  });

  NiftiHeader sheared = both; // a sheared sform gives way to the qform ...
  sheared.srow[1] = 1;
  WriteNifti(Dir() + "/sheared.nii", sheared);
  ExpectPlacedAt(Dir() + "/sheared.nii", turnedRas);
  sheared.qformCode = 0; // ... and without one is an error
  WriteNifti(Dir() + "/sheared-alone.nii", sheared);
  EXPECT_THROW(
    {
      try
      {
        art::LoadVolume(Dir() + "/sheared-alone.nii");
      }
      catch (const art::Error& e)
      {
        EXPECT_NE(std::string(e.what()).find("sheared"), std::string::npos) << e.what();
        throw;
      }
    },
    art::Error);

  NiftiHeader none; // neither: spacing only, as before (NIfTI's method 1)
  WriteNifti(Dir() + "/none.nii", none);
  ExpectPlacedAt(Dir() + "/none.nii", [](int i, int j, int k) {
    return std::array<double, 3>{ -2.0 * i, -3.0 * j, 4.0 * k };
  });
}

TEST(Formats, MetaImageHeaderWithSeparateRaw)
{
  auto img = SmallVolume();
  vtkNew<vtkMetaImageWriter> w;
  w->SetInputData(img);
  w->SetFileName((Dir() + "/split.mhd").c_str());
  w->SetRAWFileName((Dir() + "/split.raw").c_str());
  w->SetCompression(false);
  w->Write();
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/split.mhd"));
  // The header names a raw file that is too short: a clear error, not a half-read volume.
  fs::resize_file(Dir() + "/split.raw", 100);
  EXPECT_THROW(art::LoadVolume(Dir() + "/split.mhd"), art::Error);
}

// vtkMetaImageReader drops TransformMatrix (and a negative spacing's sign): a volume ITK wrote
// with its axes turned or mirrored must still put each voxel where the header says.
TEST(Formats, MetaImageDirectionAndNegativeSpacing)
{
  auto img = SmallVolume();
  vtkNew<vtkMetaImageWriter> w;
  w->SetInputData(img);
  w->SetFileName((Dir() + "/turned.mhd").c_str());
  w->SetRAWFileName((Dir() + "/turned.raw").c_str());
  w->SetCompression(false);
  w->Write();
  auto rewrite = [&](const std::string& name, const std::string& spacing, const std::string& matrix) {
    std::ofstream f(Dir() + "/" + name);
    f << "ObjectType = Image\nNDims = 3\nDimSize = 11 5 3\nElementType = MET_SHORT\n"
      << "Offset = 10 -4 3\nElementSpacing = " << spacing << "\n"
      << (matrix.empty() ? "" : "TransformMatrix = " + matrix + "\n") << "ElementDataFile = turned.raw\n";
  };
  // ITK writes the matrix axis by axis: index axis i points along +y, j along -x, k along z.
  rewrite("turned.mhd", "0.5 0.75 2", "0 1 0 -1 0 0 0 0 1");
  auto turned = art::LoadVolume(Dir() + "/turned.mhd");
  ExpectSameVolume(img, turned);
  double p[3];
  turned->TransformContinuousIndexToPhysicalPoint(2, 1, 1, p);
  EXPECT_NEAR(p[0], 10 - 0.75, 1e-9);
  EXPECT_NEAR(p[1], -4 + 2 * 0.5, 1e-9);
  EXPECT_NEAR(p[2], 3 + 2.0, 1e-9);
  // A negative spacing turns its axis around; the size stays the spacing.
  rewrite("mirrored.mhd", "0.5 0.75 -2", "");
  auto mirrored = art::LoadVolume(Dir() + "/mirrored.mhd");
  ExpectSameVolume(img, mirrored);
  mirrored->TransformContinuousIndexToPhysicalPoint(0, 0, 2, p);
  EXPECT_NEAR(p[2], 3 - 4.0, 1e-9);
  EXPECT_NEAR(p[0], 10, 1e-9);
  // The identity stays the identity.
  rewrite("plain.mhd", "0.5 0.75 2", "1 0 0 0 1 0 0 0 1");
  EXPECT_TRUE(art::LoadVolume(Dir() + "/plain.mhd")->GetDirectionMatrix()->IsIdentity());
}

// VTK's XML and legacy formats keep a spacing's sign; the voxel reference took it as positive and
// rendered such a volume mirrored against its reduced mesh. Loaded, the sign is in the direction
// and every voxel stays where the file put it. A zero spacing puts an axis in one plane: an error.
TEST(Formats, VtiAndLegacySpacingSign)
{
  auto img = SmallVolume();
  img->SetSpacing(0.5, -0.75, 2.0);
  img->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1);
  WriteVolume<vtkXMLImageDataWriter>(img, Dir() + "/negative.vti");
  WriteVolume<vtkDataSetWriter>(img, Dir() + "/negative.vtk"); // legacy: no direction
  for (const std::string name : { "negative.vti", "negative.vtk" })
  {
    SCOPED_TRACE(name);
    auto v = art::LoadVolume(Dir() + "/" + name);
    EXPECT_EQ(v->GetSpacing()[1], 0.75);
    const bool legacy = name == "negative.vtk";
    double want[3], got[3];
    for (int k = 0; k < 3; k += 2)
      for (int j = 0; j < 5; j += 4)
        for (int i = 0; i < 11; i += 10)
        {
          if (legacy)
          {
            want[0] = 10 + 0.5 * i, want[1] = -4 - 0.75 * j, want[2] = 3 + 2.0 * k;
          }
          else
          {
            img->TransformIndexToPhysicalPoint(i, j, k, want);
          }
          v->TransformIndexToPhysicalPoint(i, j, k, got);
          for (int a = 0; a < 3; ++a)
          {
            EXPECT_NEAR(got[a], want[a], 1e-12) << "voxel " << i << " " << j << " " << k;
          }
        }
    EXPECT_EQ(v->GetPointData()->GetScalars()->GetTuple1(3 + 11 * 4), img->GetPointData()->GetScalars()->GetTuple1(3 + 11 * 4));
  }
  img->SetSpacing(0.5, 0, 2.0);
  WriteVolume<vtkXMLImageDataWriter>(img, Dir() + "/flat.vti");
  try
  {
    art::LoadVolume(Dir() + "/flat.vti");
    ADD_FAILURE() << "a zero spacing loaded";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("flat.vti: spacing along y is 0"), std::string::npos) << e.what();
  }
}

// vtkNrrdReader takes a fastest axis of 9 or fewer samples for vector components (its own
// heuristic), so this volume is 11 wide.
TEST(Formats, NrrdWrittenByHand)
{
  auto img = SmallVolume();
  const std::string p = Dir() + "/v.nrrd";
  {
    std::ofstream f(p, std::ios::binary);
    f << "NRRD0004\ntype: short\ndimension: 3\nsizes: 11 5 3\nkinds: domain domain domain\n"
         "spacings: 0.5 0.75 2\n"
         "encoding: raw\nendian: little\n\n";
    auto* s = vtkShortArray::SafeDownCast(img->GetPointData()->GetScalars());
    f.write(reinterpret_cast<const char*>(s->GetPointer(0)), s->GetNumberOfTuples() * 2);
  }
  ExpectSameVolume(img, art::LoadVolume(p), false);
}

// vtkNrrdReader keeps only the lengths of "space directions" as the spacing: their signs and
// rotation (Slicer writes them on every volume) must reach the direction matrix.
TEST(Formats, NrrdSpaceDirections)
{
  auto img = SmallVolume();
  auto write = [&](const std::string& name, const std::string& directions) {
    std::ofstream f(Dir() + "/" + name, std::ios::binary);
    f << "NRRD0004\n# turned\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
         "sizes: 11 5 3\nspace directions: " << directions << "\nkinds: domain domain domain\n"
         "space origin: (10,-4,3)\nencoding: raw\nendian: little\n\n";
    auto* s = vtkShortArray::SafeDownCast(img->GetPointData()->GetScalars());
    f.write(reinterpret_cast<const char*>(s->GetPointer(0)), s->GetNumberOfTuples() * 2);
  };
  // Index axis i points along +y, j along -x, k along +z.
  write("turned.nrrd", "(0,0.5,0) (-0.75,0,0) (0,0,2)");
  auto turned = art::LoadVolume(Dir() + "/turned.nrrd");
  ExpectSameVolume(img, turned);
  double p[3];
  turned->TransformContinuousIndexToPhysicalPoint(2, 1, 1, p);
  EXPECT_NEAR(p[0], 10 - 0.75, 1e-9);
  EXPECT_NEAR(p[1], -4 + 2 * 0.5, 1e-9);
  EXPECT_NEAR(p[2], 3 + 2.0, 1e-9);
  write("plain.nrrd", "(0.5,0,0) (0,0.75,0) (0,0,2)");
  EXPECT_TRUE(art::LoadVolume(Dir() + "/plain.nrrd")->GetDirectionMatrix()->IsIdentity());
  write("zero.nrrd", "(0.5,0,0) (0,0,0) (0,0,2)");
  EXPECT_THROW(art::LoadVolume(Dir() + "/zero.nrrd"), art::Error);
}

// vtkNrrdReader read a first axis of 9 or fewer samples as vector components even when the header
// calls it a domain axis: a 4 x 3 x 2 volume loaded as 3 x 2 x 1 voxels of 4 components with the
// spacing of the wrong axes. It ignores "space" (a RAS file, x and y opposite to LPS, was placed
// as if LPS), and in a left-handed space (LAS) it reverses the rows but keeps the origin (a
// mirror). Voxel v = i + nx (j + 3 k) of the file lies where the header puts it, in LPS.
TEST(Formats, NrrdNarrowFirstAxisAndSpaces)
{
  auto write = [](const std::string& name, int nx, const std::string& fields) {
    std::ofstream f(Dir() + "/" + name, std::ios::binary);
    f << "NRRD0004\ntype: short\ndimension: 3\nsizes: " << nx << " 3 2\n" << fields << "encoding: raw\nendian: little\n\n";
    for (short v = 0; v < nx * 6; ++v)
    {
      f.write(reinterpret_cast<const char*>(&v), 2);
    }
  };
  auto expectAt = [](const std::string& name, int nx, const std::array<double, 3>& o, const std::array<double, 3>& step) {
    auto img = art::LoadVolume(Dir() + "/" + name);
    int d[3];
    img->GetDimensions(d);
    ASSERT_EQ(d[0], nx) << name;
    ASSERT_EQ(d[1], 3) << name;
    ASSERT_EQ(d[2], 2) << name;
    vtkDataArray* s = img->GetPointData()->GetScalars();
    ASSERT_EQ(s->GetNumberOfComponents(), 1) << name;
    for (int I = 0; I < nx * 6; ++I)
    {
      const int v = static_cast<int>(s->GetTuple1(I));
      const int file[3] = { v % nx, v / nx % 3, v / (3 * nx) };
      double x[3];
      img->TransformContinuousIndexToPhysicalPoint(I % nx, I / nx % 3, I / (3 * nx), x);
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_NEAR(x[a], o[a] + step[a] * file[a], 1e-9) << name << " voxel " << v << " axis " << a;
      }
    }
  };
  const std::string directions = "space directions: (0.5,0,0) (0,2,0) (0,0,3)\nspace origin: (10,20,30)\n";
  for (const int nx : { 4, 11 })
  {
    const std::string n = std::to_string(nx);
    write("kinds-" + n + ".nrrd", nx, "kinds: domain domain domain\nspacings: 0.5 2 3\n");
    expectAt("kinds-" + n + ".nrrd", nx, { 0, 0, 0 }, { 0.5, 2, 3 });
    write("lps-" + n + ".nrrd", nx, "space: left-posterior-superior\n" + directions);
    expectAt("lps-" + n + ".nrrd", nx, { 10, 20, 30 }, { 0.5, 2, 3 });
    write("ras-" + n + ".nrrd", nx, "space: right-anterior-superior\n" + directions);
    expectAt("ras-" + n + ".nrrd", nx, { -10, -20, 30 }, { -0.5, -2, 3 });
    write("las-" + n + ".nrrd", nx, "space: LAS\n" + directions);
    expectAt("las-" + n + ".nrrd", nx, { 10, -20, 30 }, { 0.5, -2, 3 });
    write("left-handed-" + n + ".nrrd", nx, "space: 3D-left-handed\n" + directions);
    expectAt("left-handed-" + n + ".nrrd", nx, { 10, 20, 30 }, { 0.5, 2, 3 });
    // A minimal header (type, dimension, sizes, encoding: as unu and pynrrd write them) names
    // neither kinds nor directions: three axes are a volume (4 x 3 x 2 was read as 3 x 2 x 1
    // voxels of 4 components).
    write("minimal-" + n + ".nrrd", nx, "");
    expectAt("minimal-" + n + ".nrrd", nx, { 0, 0, 0 }, { 1, 1, 1 });
    write("spacings-" + n + ".nrrd", nx, "spacings: 0.5 2 3\n");
    expectAt("spacings-" + n + ".nrrd", nx, { 0, 0, 0 }, { 0.5, 2, 3 });
  }
  // A first axis the header calls a vector stays the components.
  write("vectors.nrrd", 4, "kinds: vector domain domain\n");
  EXPECT_EQ(art::LoadVolume(Dir() + "/vectors.nrrd")->GetPointData()->GetScalars()->GetNumberOfComponents(), 4);
}

// NRRD text data (encoding ascii/text, as hand-made and teaching files hold it): vtkNrrdReader read
// every voxel as 0 without a word. Attached and detached, with the values in file order.
TEST(Formats, NrrdTextData)
{
  const std::string head = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nencoding: ascii\n";
  std::string values;
  for (int v = 0; v < 24; ++v)
  {
    values += std::to_string(3 * v - 20) + (v % 5 == 4 ? "\n" : " ");
  }
  std::ofstream(Dir() + "/text.nrrd", std::ios::binary) << head << "\n" << values << "\n";
  std::ofstream(Dir() + "/text.txt", std::ios::binary) << values;
  std::ofstream(Dir() + "/text.nhdr", std::ios::binary) << head << "data file: text.txt\n";
  for (const char* name : { "/text.nrrd", "/text.nhdr" })
  {
    auto img = art::LoadVolume(Dir() + name);
    int d[3];
    img->GetDimensions(d);
    ASSERT_EQ(d[0] * 10 + d[1] * 100 + d[2] * 1000, 4 * 10 + 3 * 100 + 2 * 1000) << name;
    vtkDataArray* s = img->GetPointData()->GetScalars();
    ASSERT_EQ(s->GetNumberOfComponents(), 1) << name;
    for (int v = 0; v < 24; ++v)
    {
      EXPECT_EQ(s->GetTuple1(v), 3 * v - 20) << name << " voxel " << v;
    }
  }
  std::ofstream(Dir() + "/text-short.nrrd", std::ios::binary) << head << "\n1 2 3\n";
  EXPECT_THROW(art::LoadVolume(Dir() + "/text-short.nrrd"), art::Error);
  std::ofstream(Dir() + "/text-word.nrrd", std::ios::binary) << head << "\n1 2 x\n";
  EXPECT_THROW(art::LoadVolume(Dir() + "/text-word.nrrd"), art::Error);
}

TEST(Formats, DicomSeriesFolder)
{
  // tests/data/dicom: 4 slices of 16 x 12 cut from the default CT (tests/data/make_dicom.py).
  auto img = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/tests/data/dicom");
  int d[3];
  img->GetDimensions(d);
  EXPECT_EQ(d[0], 16);
  EXPECT_EQ(d[1], 12);
  EXPECT_EQ(d[2], 4);
  EXPECT_NEAR(img->GetSpacing()[0], 1.914, 1e-4);
  EXPECT_NEAR(img->GetSpacing()[2], 3.0, 1e-4);
  double sum = 0;
  vtkDataArray* s = img->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    sum += s->GetTuple1(i);
  }
  EXPECT_EQ(sum, 13104.0); // the crop's sum, printed by make_dicom.py
}

// vtkDICOMImageReader keeps rows bottom-up and slices far-to-near with origin 0 and no
// direction, and swaps PixelSpacing's pair: a series with turned axes and non-square pixels came
// out rotated and stretched against the same voxels from ITK or a MetaImage. Each voxel must land
// at ImagePositionPatient + i * 0.7 * r + j * 0.9 * c + k * 1.5 * n (tests/data/make_dicom_rotated.py).
TEST(Formats, DicomPatientGeometry)
{
  auto img = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/tests/data/dicom-rotated");
  int d[3];
  img->GetDimensions(d);
  ASSERT_EQ(d[0], 4);
  ASSERT_EQ(d[1], 3);
  ASSERT_EQ(d[2], 3);
  EXPECT_NEAR(img->GetSpacing()[0], 0.7, 1e-6);
  EXPECT_NEAR(img->GetSpacing()[1], 0.9, 1e-6);
  const double r[3] = { 0, 1, 0 }, c[3] = { -1, 0, 0 }, n[3] = { 0, 0, 1 }, p0[3] = { 10, 20, 30 };
  vtkDataArray* s = img->GetPointData()->GetScalars();
  for (int k = 0; k < d[2]; ++k)
  {
    for (int j = 0; j < d[1]; ++j)
    {
      for (int i = 0; i < d[0]; ++i)
      {
        const int v = static_cast<int>(s->GetTuple1(i + d[0] * (j + d[1] * k)));
        const int vi = v % 10, vj = (v / 10) % 10, vk = v / 100; // the DICOM column, row, slice
        double p[3];
        img->TransformContinuousIndexToPhysicalPoint(i, j, k, p);
        for (int a = 0; a < 3; ++a)
        {
          EXPECT_NEAR(p[a], p0[a] + vi * 0.7 * r[a] + vj * 0.9 * c[a] + vk * 1.5 * n[a], 1e-5)
            << "voxel " << v << " axis " << a;
        }
      }
    }
  }
}

// An image with its values on the cells only (labels, a finite-volume simulation) "held no
// voxels": its cells are the voxels, at the cell centres, with the image's spacing and direction.
TEST(Formats, CellDataImageBecomesVoxels)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetExtent(0, 4, 0, 3, 0, 2); // 4 x 3 x 2 cells
  img->SetSpacing(0.5, 2, 3);
  img->SetOrigin(1, 2, 3);
  img->SetDirectionMatrix(-1, 0, 0, 0, 1, 0, 0, 0, 1);
  vtkNew<vtkDoubleArray> labels;
  labels->SetName("labels");
  labels->SetNumberOfTuples(24);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        labels->SetValue(i + 4 * (j + 3 * k), i + 10 * j + 100 * k);
  img->GetCellData()->SetScalars(labels);
  const std::string p = Dir() + "/cells.vti";
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(img);
  w->SetFileName(p.c_str());
  ASSERT_TRUE(w->Write());
  for (const std::string& name : { std::string(), std::string("labels") })
  {
    auto v = art::LoadVolume(p, name);
    int d[3];
    v->GetDimensions(d);
    EXPECT_EQ(d[0], 4);
    EXPECT_EQ(d[1], 3);
    EXPECT_EQ(d[2], 2);
    ASSERT_NE(v->GetPointData()->GetScalars(), nullptr);
    // Voxel (3, 2, 1) is the centre of cell (3, 2, 1): x = 1 - 3.5 * 0.5, y = 2 + 2.5 * 2, z = 3 + 1.5 * 3.
    const int* e = v->GetExtent();
    EXPECT_EQ(v->GetPointData()->GetScalars()->GetTuple1(3 + 4 * (2 + 3 * 1)), 123);
    double x[3];
    v->TransformContinuousIndexToPhysicalPoint(e[0] + 3, e[2] + 2, e[4] + 1, x);
    EXPECT_NEAR(x[0], 1 - 1.75, 1e-12);
    EXPECT_NEAR(x[1], 2 + 5.0, 1e-12);
    EXPECT_NEAR(x[2], 3 + 4.5, 1e-12);
  }
}

TEST(Formats, EverySurfaceFormatKeepsTheTriangles)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(13);
  sphere->Update();
  vtkPolyData* pd = sphere->GetOutput();
  const vtkIdType tris = pd->GetNumberOfPolys();
  ASSERT_EQ(tris, 24 * 2 * (13 - 2));

  for (const std::string name : { "s.ply", "s.obj", "s.stl", "s.vtp" })
  {
    const std::string p = Dir() + "/" + name;
    const std::string ext = name.substr(1);
    ASSERT_TRUE(ext == ".ply" ? WriteSurface<vtkPLYWriter>(pd, p)
        : ext == ".obj"       ? WriteSurface<vtkOBJWriter>(pd, p)
        : ext == ".stl"       ? WriteSurface<vtkSTLWriter>(pd, p)
                              : WriteSurface<vtkXMLPolyDataWriter>(pd, p));
    auto back = art::LoadSurface(p);
    EXPECT_EQ(back->GetNumberOfPolys(), tris) << name;
    double a[6], b[6];
    pd->GetBounds(a);
    back->GetBounds(b);
    for (int i = 0; i < 6; ++i)
    {
      EXPECT_NEAR(a[i], b[i], 1e-5) << name;
    }
  }
}

// Parallel pieces as ParaView saves them from several ranks (.pvti, .pvtp) were an "unknown file
// type". VTK 9.1 writes a .pvti without the direction its pieces keep, and its reader drops it:
// the direction comes from the .pvti or else the first piece. Pieces are written by hand here.
TEST(Formats, ParallelImageAndPolyDataPieces)
{
  auto whole = SmallVolume();
  whole->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1);
  const int slabs[2][2] = { { 0, 1 }, { 1, 2 } }; // z extents; the pieces share the plane z = 1
  for (int p = 0; p < 2; ++p)
  {
    vtkNew<vtkImageData> piece;
    piece->SetExtent(0, 10, 0, 4, slabs[p][0], slabs[p][1]);
    piece->SetSpacing(whole->GetSpacing());
    piece->SetOrigin(whole->GetOrigin());
    piece->SetDirectionMatrix(whole->GetDirectionMatrix());
    vtkNew<vtkShortArray> s;
    s->SetName("scalars");
    s->SetNumberOfTuples(11 * 5 * 2);
    for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    {
      s->SetValue(i, static_cast<short>(whole->GetPointData()->GetScalars()->GetTuple1(i + 55 * slabs[p][0])));
    }
    piece->GetPointData()->SetScalars(s);
    WriteVolume<vtkXMLImageDataWriter>(piece, Dir() + "/v_" + std::to_string(p) + ".vti");
  }
  for (const std::string direction : { "", " Direction=\"0 -1 0 1 0 0 0 0 1\"" })
  {
    std::ofstream(Dir() + "/v.pvti")
      << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<PImageData WholeExtent=\"0 10 0 4 0 2\" GhostLevel=\"0\" Origin=\"10 -4 3\" Spacing=\"0.5 0.75 2\""
      << direction << ">\n<PPointData Scalars=\"scalars\"><PDataArray type=\"Int16\" Name=\"scalars\"/></PPointData>\n"
      << "<Piece Extent=\"0 10 0 4 0 1\" Source=\"v_0.vti\"/>\n<Piece Extent=\"0 10 0 4 1 2\" Source=\"v_1.vti\"/>\n"
      << "</PImageData>\n</VTKFile>\n";
    auto v = art::LoadVolume(Dir() + "/v.pvti");
    ExpectSameVolume(whole, v);
    double want[3], got[3];
    whole->TransformIndexToPhysicalPoint(10, 4, 2, want);
    v->TransformIndexToPhysicalPoint(10, 4, 2, got);
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(got[a], want[a], 1e-12) << "direction in the .pvti: '" << direction << "'";
    }
  }

  vtkNew<vtkSphereSource> half[2];
  vtkIdType tris = 0;
  for (int p = 0; p < 2; ++p)
  {
    half[p]->SetThetaResolution(12);
    half[p]->SetStartTheta(180.0 * p);
    half[p]->SetEndTheta(180.0 * (p + 1));
    half[p]->Update();
    tris += half[p]->GetOutput()->GetNumberOfPolys();
    ASSERT_TRUE(WriteSurface<vtkXMLPolyDataWriter>(half[p]->GetOutput(), Dir() + "/s_" + std::to_string(p) + ".vtp"));
  }
  std::ofstream(Dir() + "/s.pvtp")
    << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "<PPolyData GhostLevel=\"0\"><PPointData/><PPoints><PDataArray type=\"Float32\" Name=\"Points\" "
    << "NumberOfComponents=\"3\"/></PPoints>\n<Piece Source=\"s_0.vtp\"/>\n<Piece Source=\"s_1.vtp\"/>\n"
    << "</PPolyData>\n</VTKFile>\n";
  EXPECT_EQ(art::LoadSurface(Dir() + "/s.pvtp")->GetNumberOfPolys(), tris);
}

// A legacy .vtk file is read as whatever its header holds: image data as a volume, polygons as a
// surface, unstructured, structured and rectilinear grids as a mesh (grids as hexahedra or voxels).
TEST(Formats, LegacyVtkByContentAndXmlGrids)
{
  auto img = SmallVolume();
  WriteVolume<vtkDataSetWriter>(img, Dir() + "/v.vtk");
  EXPECT_EQ(art::KindOf(Dir() + "/v.vtk"), art::DataKind::Volume);
  ExpectSameVolume(img, art::LoadVolume(Dir() + "/v.vtk"));

  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  ASSERT_TRUE(WriteSurface<vtkDataSetWriter>(sphere->GetOutput(), Dir() + "/s.vtk"));
  EXPECT_EQ(art::KindOf(Dir() + "/s.vtk"), art::DataKind::Surface);
  EXPECT_EQ(art::LoadSurface(Dir() + "/s.vtk")->GetNumberOfPolys(), sphere->GetOutput()->GetNumberOfPolys());

  // The same 11 x 5 x 3 points as a structured grid (legacy and XML) and a rectilinear grid.
  vtkNew<vtkImageDataToPointSet> toGrid;
  toGrid->SetInputData(img);
  toGrid->Update();
  vtkNew<vtkRectilinearGrid> rect;
  rect->SetDimensions(11, 5, 3);
  vtkNew<vtkDoubleArray> axis[3];
  for (int a = 0; a < 3; ++a)
  {
    for (int i = 0; i < img->GetDimensions()[a]; ++i)
    {
      axis[a]->InsertNextValue(img->GetOrigin()[a] + i * img->GetSpacing()[a]);
    }
  }
  rect->SetXCoordinates(axis[0]);
  rect->SetYCoordinates(axis[1]);
  rect->SetZCoordinates(axis[2]);
  rect->GetPointData()->SetScalars(img->GetPointData()->GetScalars());
  WriteVolume<vtkDataSetWriter>(toGrid->GetOutput(), Dir() + "/g.vtk");
  WriteVolume<vtkXMLStructuredGridWriter>(toGrid->GetOutput(), Dir() + "/g.vts");
  WriteVolume<vtkXMLRectilinearGridWriter>(rect, Dir() + "/g.vtr");
  for (const std::string name : { "g.vtk", "g.vts", "g.vtr" })
  {
    EXPECT_EQ(art::KindOf(Dir() + "/" + name), art::DataKind::Mesh) << name;
    auto ug = art::LoadMesh(Dir() + "/" + name);
    EXPECT_EQ(ug->GetNumberOfCells(), 10 * 4 * 2) << name;
    EXPECT_TRUE(ug->GetCellType(0) == VTK_HEXAHEDRON || ug->GetCellType(0) == VTK_VOXEL) << name;
    ASSERT_NE(ug->GetPointData()->GetScalars(), nullptr) << name;
    EXPECT_EQ(ug->GetPointData()->GetScalars()->GetTuple1(17), img->GetPointData()->GetScalars()->GetTuple1(17));
  }

  std::ofstream(Dir() + "/junk.vtk") << "not a VTK file\n";
  try
  {
    art::KindOf(Dir() + "/junk.vtk");
    ADD_FAILURE() << "junk.vtk was classified";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("junk.vtk: is not a legacy VTK data set"), std::string::npos) << e.what();
  }
}

// A volume with several arrays and none active: the first single-component array is taken, a
// named one on request, and a missing name lists what there is.
TEST(Formats, VolumeArraySelection)
{
  auto img = SmallVolume();
  vtkNew<vtkDoubleArray> twice;
  twice->SetName("twice");
  twice->SetNumberOfTuples(img->GetNumberOfPoints());
  for (vtkIdType i = 0; i < twice->GetNumberOfTuples(); ++i)
  {
    twice->SetValue(i, 2 * img->GetPointData()->GetScalars()->GetTuple1(i));
  }
  img->GetPointData()->AddArray(twice);
  img->GetPointData()->SetActiveScalars(nullptr);
  WriteVolume<vtkXMLImageDataWriter>(img, Dir() + "/two.vti");
  EXPECT_EQ(std::string(art::LoadVolume(Dir() + "/two.vti")->GetPointData()->GetScalars()->GetName()), "scalars");
  auto t = art::LoadVolume(Dir() + "/two.vti", "twice");
  EXPECT_EQ(t->GetPointData()->GetScalars()->GetTuple1(3), twice->GetValue(3));
  try
  {
    art::LoadVolume(Dir() + "/two.vti", "density");
    ADD_FAILURE() << "a missing array loaded";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("no point array 'density' (it has: scalars, twice)"), std::string::npos)
      << e.what();
  }
}
