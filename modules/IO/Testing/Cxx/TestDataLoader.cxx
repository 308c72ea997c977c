#include "DataLoader.h"
#include "Error.h"

#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <string>

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

TEST(DataLoader, WrongKindForTheCall)
{
  EXPECT_THROW(art::LoadSurface(Data + "ct-head-128.mha"), art::Error);
  EXPECT_THROW(art::LoadVolume(Data + "am_underworks.ply"), art::Error);
}
