// Files VTK 9.1's readers crash on, hang on or read silently wrong: each is made here (from a good
// file VTK writes, then damaged as a disk, a copy or a tool damages it) and must give one
// art::Error naming the file and the cause, within a second, and no crash.
#include "AtomicFile.h"
#include "DataLoader.h"
#include "Error.h"
#include "ReaderRun.h"

#include <vtkDataSetTriangleFilter.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMetaImageReader.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkRTAnalyticSource.h>
#include <vtkSphereSource.h>
#include <vtkStripper.h>
#include <vtkStructuredPointsWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
std::string Dir()
{
  const fs::path d = fs::path(ART_TEST_OUTPUT) / "TestBadFiles";
  fs::create_directories(d);
  return d.string();
}

std::string Read(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void Write(const std::string& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
}

vtkSmartPointer<vtkImageData> Wavelet()
{
  vtkNew<vtkRTAnalyticSource> src;
  src->SetWholeExtent(0, 15, 0, 15, 0, 15);
  src->Update();
  return src->GetOutput();
}

vtkSmartPointer<vtkUnstructuredGrid> Tets()
{
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputData(Wavelet());
  tri->Update();
  return tri->GetOutput();
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> s;
  s->SetThetaResolution(30);
  s->Update();
  return s->GetOutput();
}

// Loads `path` expecting one art::Error that names it and matches `cause`, within a second.
void ExpectRefused(const std::string& path, const std::string& cause)
{
  const auto t0 = std::chrono::steady_clock::now();
  try
  {
    art::Load(path);
    ADD_FAILURE() << path << " loaded; expected an error matching '" << cause << "'";
  }
  catch (const art::Error& e)
  {
    const std::string what = e.what();
    EXPECT_EQ(e.file(), path);
    EXPECT_TRUE(std::regex_search(what, std::regex(cause))) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(s, 2.0) << path;
}

std::string AppendedVti(bool compressed)
{
  const std::string path = Dir() + (compressed ? "/wavelet-z.vti" : "/wavelet.vti");
  vtkNew<vtkXMLImageDataWriter> w;
  w->SetInputData(Wavelet());
  w->SetFileName(path.c_str());
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  if (!compressed)
  {
    w->SetCompressorTypeToNone();
  }
  w->Write();
  return path;
}
} // namespace

TEST(BadFiles, NrrdDimensionOutOfRange)
{
  for (int d : { 0, 17 })
  {
    const std::string p = Dir() + "/dim" + std::to_string(d) + ".nrrd";
    Write(p, "NRRD0004\ntype: float\ndimension: " + std::to_string(d) + "\nsizes: 4 4 4\nencoding: raw\n\n" +
        std::string(256, '\0'));
    ExpectRefused(p, "dimension '" + std::to_string(d) + "' is not 1\\.\\.16");
  }
  const std::string p = Dir() + "/sizes-short.nrrd";
  Write(p, "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 4\nencoding: raw\n\n" + std::string(64, '\0'));
  ExpectRefused(p, "lists 2 sizes for dimension 3");
}

TEST(BadFiles, NegativeXmlCountAndDeepNesting)
{
  const std::string good = Dir() + "/tets-ascii.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(Tets());
  w->SetFileName(good.c_str());
  w->SetDataModeToAscii();
  w->Write();
  const std::string bad = Dir() + "/negative-cells.vtu";
  Write(bad, std::regex_replace(Read(good), std::regex("NumberOfCells=\"\\d+\""), "NumberOfCells=\"-5\""));
  ExpectRefused(bad, "NumberOfCells=\"-5\" is not a count");

  std::string nested = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\"><UnstructuredGrid>";
  for (int i = 0; i < 200000; ++i)
  {
    nested += "<a>";
  }
  for (int i = 0; i < 200000; ++i)
  {
    nested += "</a>";
  }
  nested += "</UnstructuredGrid></VTKFile>\n";
  Write(Dir() + "/nested.vtu", nested);
  ExpectRefused(Dir() + "/nested.vtu", "nest more than 128 deep");
}

TEST(BadFiles, AppendedImageCutShort)
{
  for (bool compressed : { false, true })
  {
    const std::string bytes = Read(AppendedVti(compressed));
    ASSERT_GT(bytes.size(), 10000u);
    for (double f : { 0.1, 0.5, 0.9, 0.999 })
    {
      const std::string p = Dir() + "/cut" + std::to_string(int(f * 1000)) + (compressed ? "z" : "") + ".vti";
      Write(p, bytes.substr(0, static_cast<std::size_t>(bytes.size() * f)));
      ExpectRefused(p, "truncated");
    }
    // Cut inside the data with the end tags put back: the array's length reaches past the end.
    const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
    const std::string p = Dir() + (compressed ? "/cut-inside-z.vti" : "/cut-inside.vti");
    Write(p, bytes.substr(0, bytes.size() * 9 / 10) + tail);
    ExpectRefused(p, "truncated: the appended data of array");
  }
}

// Base64 appended data (VTK's writers' default) read whole, compressed or not, and a block count
// past what the file holds is refused (VTK allocated for billions of blocks).
TEST(BadFiles, Base64AppendedData)
{
  for (bool compressed : { false, true })
  {
    const std::string p = Dir() + (compressed ? "/base64-z.vti" : "/base64.vti");
    vtkNew<vtkXMLImageDataWriter> w;
    w->SetInputData(Wavelet());
    w->SetFileName(p.c_str());
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOn();
    if (!compressed)
    {
      w->SetCompressorTypeToNone();
    }
    w->Write();
    auto img = art::LoadVolume(p);
    EXPECT_EQ(img->GetNumberOfPoints(), 16 * 16 * 16);
    EXPECT_EQ(img->GetPointData()->GetScalars()->GetTuple1(100), Wavelet()->GetPointData()->GetScalars()->GetTuple1(100));
    std::string bytes = Read(p);
    const std::size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
    bytes.replace(data, 8, "////////"); // the first array's length (or block count): 2^32 - 1
    const std::string bad = Dir() + (compressed ? "/base64-z-bad.vti" : "/base64-bad.vti");
    Write(bad, bytes);
    ExpectRefused(bad, "the base64 appended data of array 'RTData' claim");
  }
}

TEST(BadFiles, NanSpacingInXml)
{
  const std::string good = Read(AppendedVti(false));
  const std::string p = Dir() + "/nan-spacing.vti";
  Write(p, std::regex_replace(good, std::regex("Spacing=\"[^\"]*\""), "Spacing=\"nan nan nan\""));
  ExpectRefused(p, "Spacing=\"nan nan nan\" is not 3 finite numbers");
}

TEST(BadFiles, BinaryMeshCutByAThousandth)
{
  const std::string good = Dir() + "/tets.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(Tets());
  w->SetFileName(good.c_str());
  w->SetDataModeToBinary();
  w->Write();
  const std::string bytes = Read(good);
  Write(Dir() + "/tets-cut.vtu", bytes.substr(0, bytes.size() - bytes.size() / 1000));
  ExpectRefused(Dir() + "/tets-cut.vtu", "truncated");
  EXPECT_EQ(art::LoadMesh(good)->GetNumberOfCells(), Tets()->GetNumberOfCells());
}

TEST(BadFiles, LegacyFilesCutShort)
{
  const std::string vol = Dir() + "/wavelet.vtk", surf = Dir() + "/sphere.vtk", text = Dir() + "/sphere-ascii.vtk";
  vtkNew<vtkStructuredPointsWriter> wv;
  wv->SetInputData(Wavelet());
  wv->SetFileName(vol.c_str());
  wv->SetFileTypeToBinary();
  wv->Write();
  for (const std::string& p : { surf, text })
  {
    vtkNew<vtkPolyDataWriter> ws;
    ws->SetInputData(Sphere());
    ws->SetFileName(p.c_str());
    if (p == surf)
    {
      ws->SetFileTypeToBinary();
    }
    ws->Write();
  }
  for (const std::string& p : { vol, surf, text })
  {
    EXPECT_NO_THROW(art::Load(p)) << p;
    const std::string bytes = Read(p);
    const std::string cut = p.substr(0, p.size() - 4) + "-cut.vtk";
    Write(cut, bytes.substr(0, bytes.size() * 7 / 10));
    ExpectRefused(cut, "cannot read: Error reading (binary|ascii) data");
  }
}

TEST(BadFiles, MeshNamingAPointPastTheLast)
{
  const std::string good = Dir() + "/tets-ascii-index.vtu";
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(Tets());
  w->SetFileName(good.c_str());
  w->SetDataModeToAscii();
  w->Write();
  // The connectivity's first value becomes 1000000000.
  std::string text = Read(good);
  const std::size_t at = text.find("Name=\"connectivity\"");
  ASSERT_NE(at, std::string::npos);
  const std::size_t start = text.find('>', at) + 1;
  const std::size_t first = text.find_first_of("0123456789", start);
  const std::size_t end = text.find_first_not_of("0123456789", first);
  text.replace(first, end - first, "1000000000");
  Write(Dir() + "/far-vertex.vtu", text);
  ExpectRefused(Dir() + "/far-vertex.vtu", "a cell refers to point 1000000000 of 4096");
}

TEST(BadFiles, DicomSlicesShortOrEmpty)
{
  const fs::path src = fs::path(ART_SOURCE_DIR) / "tests/data/dicom";
  const fs::path cut = fs::path(Dir()) / "dicom-cut", empty = fs::path(Dir()) / "dicom-empty";
  for (const fs::path& d : { cut, empty })
  {
    fs::remove_all(d);
    fs::create_directories(d);
    for (const auto& f : fs::directory_iterator(src))
    {
      fs::copy_file(f.path(), d / f.path().filename());
    }
  }
  EXPECT_NO_THROW(art::LoadVolume(cut.string()));
  for (const auto& f : fs::directory_iterator(cut))
  {
    fs::resize_file(f.path(), fs::file_size(f.path()) - 100);
  }
  ExpectRefused(cut.string(), "slice slice_00[0-3]\\.dcm is cut short: its 16 x 12 pixels need 384 bytes, it holds 284");
  Write((empty / "slice_004.dcm").string(), "");
  ExpectRefused(empty.string(), "slice slice_004\\.dcm is empty \\(0 bytes\\)");
}

TEST(BadFiles, MetaImageTypeAgainstDataSize)
{
  std::string floats(64 * 4, '\0');
  for (int i = 0; i < 64; ++i)
  {
    const float v = float(i);
    std::memcpy(&floats[4 * i], &v, 4);
  }
  const std::string head = "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = ";
  Write(Dir() + "/char-over-float.mha", head + "MET_CHAR\nElementDataFile = LOCAL\n" + floats);
  ExpectRefused(Dir() + "/char-over-float.mha", "holds 256 data bytes where DimSize 4 4 4 of MET_CHAR needs 64 \\(4 times");
  Write(Dir() + "/float.mha", head + "MET_FLOAT\nElementDataFile = LOCAL\n" + floats);
  auto img = art::LoadVolume(Dir() + "/float.mha");
  EXPECT_EQ(img->GetPointData()->GetScalars()->GetTuple1(63), 63.0);
}

TEST(BadFiles, NiftiZeroSpacingWithoutSform)
{
  unsigned char h[352] = {};
  const std::int32_t size = 348;
  std::memcpy(h, &size, 4);
  const std::int16_t dim[8] = { 3, 4, 4, 4, 1, 1, 1, 1 }, datatype = 2, bitpix = 8;
  std::memcpy(h + 40, dim, sizeof dim);
  std::memcpy(h + 70, &datatype, 2);
  std::memcpy(h + 72, &bitpix, 2);
  const float pixdim[8] = { 1, 1, 0, 1, 1, 1, 1, 1 }, offset = 352;
  std::memcpy(h + 76, pixdim, sizeof pixdim);
  std::memcpy(h + 108, &offset, 4);
  std::memcpy(h + 344, "n+1\0", 4);
  Write(Dir() + "/pixdim0.nii", std::string(reinterpret_cast<char*>(h), sizeof h) + std::string(64, '\x07'));
  ExpectRefused(Dir() + "/pixdim0.nii", "pixdim\\[2\\] is 0 and no sform gives the spacing");
}

TEST(BadFiles, FifoAndDevicesAreRefusedAtOnce)
{
  const std::string fifo = Dir() + "/pipe.mha", zero = Dir() + "/zero.mha";
  fs::remove(fifo);
  fs::remove(zero);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", zero);
  ExpectRefused(fifo, "is a FIFO \\(named pipe\\), not a regular file");
  ExpectRefused(zero, "is a character device, not a regular file");
  // A header naming a FIFO as its data file.
  const std::string mhd = Dir() + "/fifo-data.mhd";
  Write(mhd, "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = pipe.mha\n");
  ExpectRefused(mhd, "data file 'pipe.mha' named in the header: is a FIFO");
}

TEST(BadFiles, WriteProtectedOutputIsNotReplaced)
{
  const std::string out = Dir() + "/protected.vtu";
  Write(out, "precious");
  fs::permissions(out, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  try
  {
    art::SaveMesh(Tets(), out);
    ADD_FAILURE() << "a write-protected file was replaced";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("is write-protected: not replaced"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Read(out), "precious");
  fs::permissions(out, fs::perms::owner_all);
  const std::string fifo = Dir() + "/output-fifo.vtu";
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  try
  {
    art::SaveMesh(Tets(), fifo);
    ADD_FAILURE() << "a FIFO was replaced";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("exists and is a FIFO (named pipe), not a regular file: not replaced"),
      std::string::npos)
      << e.what();
  }
}

TEST(BadFiles, BinaryBytesAreEscapedInErrors)
{
  const std::string p = Dir() + "/binary-header.mha";
  Write(p, std::string("Obj\x01\x02\x1b[31m\n\xff\xfe = 3\n", 17) + std::string(10, '\0'));
  try
  {
    art::Load(p);
    ADD_FAILURE() << "loaded";
  }
  catch (const art::Error& e)
  {
    const std::string what = e.what();
    for (unsigned char c : what)
    {
      EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "byte " << int(c) << " in '" << what << "'";
    }
  }
  EXPECT_EQ(art::Printable("a\nb\x1b\xff\xc3\xa9"), "a\\x0Ab\\x1B\\xFF\xc3\xa9");
}

// What VTK's own code prints (MetaIO's lines on std::cerr, the legacy readers' warnings) stays off
// the terminal while a reader runs; the error says it in one line.
TEST(BadFiles, ReadersPrintNothingOfTheirOwn)
{
  const std::string p = Dir() + "/spacing-first.mha";
  Write(p, "ObjectType = Image\nElementSpacing = 1 1 1\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
           "ElementDataFile = LOCAL\n" + std::string(8, '\0'));
  vtkNew<vtkMetaImageReader> reader; // past the loader's own checks, straight to MetaIO
  reader->SetFileName(p.c_str());
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  EXPECT_THROW(art::RunReader(reader, p), art::Error);
  const std::string out = testing::internal::GetCapturedStdout(), err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(err + out, "");
  ExpectRefused(p, "ElementSpacing comes before NDims in the header");
}

TEST(BadFiles, StripsAndPlacementAreRecorded)
{
  vtkNew<vtkStripper> strip;
  strip->SetInputData(Sphere());
  strip->Update();
  const std::string p = Dir() + "/strips.vtp";
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(strip->GetOutput());
  w->SetFileName(p.c_str());
  w->Write();
  auto pd = art::LoadSurface(p);
  EXPECT_EQ(pd->GetNumberOfStrips(), strip->GetOutput()->GetNumberOfStrips());
  EXPECT_TRUE(pd->GetFieldData()->GetAbstractArray("Frame"));
  auto img = art::LoadVolume(AppendedVti(false));
  auto* m = vtkDataArray::SafeDownCast(img->GetFieldData()->GetArray("IndexToWorld"));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->GetNumberOfComponents(), 16);
  // The wavelet: extent from 0, origin 0, spacing 1; its index-to-world matrix is the identity.
  EXPECT_EQ(m->GetComponent(0, 0), 1.0);
  EXPECT_EQ(m->GetComponent(0, 3), 0.0);
}
