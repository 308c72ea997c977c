#include "AtomicFile.h"
#include "Error.h"
#include "ImageIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using art::Image;

namespace
{
std::string TempDir()
{
  const fs::path d = fs::path(ART_TEST_OUTPUT) / "TestImageIO";
  fs::create_directories(d);
  return d.string();
}

Image RandomFloats(int w, int h)
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> u(-0.5f, 2.0f); // EXR keeps values outside [0, 1]
  Image img(w, h);
  for (float& v : img.Pixels())
  {
    v = u(rng);
  }
  img.Pixel(0, 0)[0] = 1e-30f; // a denormal-adjacent value survives too
  return img;
}

size_t CountTemps(const std::string& dir)
{
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
  {
    n += e.path().filename().string().find(".tmp") != std::string::npos;
  }
  return n;
}
}

TEST(ImageIO, ExrRoundTripIsBitExact)
{
  const Image a = RandomFloats(37, 23);
  const std::string p = TempDir() + "/roundtrip.exr";
  art::WriteImage(a, p);
  const Image b = art::ReadImage(p);
  ASSERT_EQ(b.Width(), 37);
  ASSERT_EQ(b.Height(), 23);
  EXPECT_EQ(std::memcmp(a.Pixels().data(), b.Pixels().data(), a.Pixels().size() * sizeof(float)), 0);
}

TEST(ImageIO, TiffRoundTripIsBitExact)
{
  const Image a = RandomFloats(16, 9);
  const std::string p = TempDir() + "/roundtrip.tif";
  art::WriteImage(a, p);
  const Image b = art::ReadImage(p);
  EXPECT_EQ(std::memcmp(a.Pixels().data(), b.Pixels().data(), a.Pixels().size() * sizeof(float)), 0);
}

TEST(ImageIO, PngQuantisesTo8BitsAndKeepsRowOrder)
{
  Image a(256, 2);
  for (int x = 0; x < 256; ++x)
  {
    a.Set(x, 0, { x / 255.f, 1.f - x / 255.f, 0.f, 1.f });
    a.Set(x, 1, { 0.f, 0.f, 1.f, x / 255.f });
  }
  const std::string p = TempDir() + "/levels.png";
  art::WriteImage(a, p);
  const Image b = art::ReadImage(p);
  for (int x = 0; x < 256; ++x)
  {
    EXPECT_NEAR(b.Pixel(x, 0)[0], x / 255.f, 1e-6);
    EXPECT_NEAR(b.Pixel(x, 0)[1], 1.f - x / 255.f, 1e-6);
    EXPECT_NEAR(b.Pixel(x, 1)[2], 1.f, 1e-6);
    EXPECT_NEAR(b.Pixel(x, 1)[3], x / 255.f, 1e-6);
  }
}

namespace
{
bool OpenImageIOLoaded()
{
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
  {
    if (line.find("libOpenImageIO") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
}

// Before main and any test: a library the program links is loaded by now.
const bool OpenImageIOAtStart = OpenImageIOLoaded();

// OpenImageIO's ~260 libraries cost every program linking it half a second at start-up, so it is
// a plug-in loaded on the first image that is not a PNG. (ctest runs each test in its own process.)
TEST(ImageIO, OpenImageIOIsLoadedOnlyForOtherFormats)
{
  EXPECT_FALSE(OpenImageIOAtStart) << "OpenImageIO came with the program: linked, not a plug-in";
  if (OpenImageIOLoaded())
  {
    GTEST_SKIP() << "an earlier test in this process loaded it";
  }
  const std::string p = TempDir() + "/lazy.png";
  art::WriteImage(Image(3, 2, { 0.5f, 0.25f, 1.f, 1.f }), p);
  EXPECT_NEAR(art::ReadImage(p).Pixel(2, 1)[1], 64 / 255.f, 1e-6);
  EXPECT_FALSE(OpenImageIOLoaded());
  art::WriteImage(Image(3, 2, { 0.5f, 0.25f, 1.f, 1.f }), TempDir() + "/lazy.exr");
  EXPECT_TRUE(OpenImageIOLoaded());
}

TEST(ImageIO, FailedWriteLeavesExistingFileAndNoTemp)
{
  // Its own folder: ctest runs the other tests at the same time, and their temporaries would count.
  const std::string dir = TempDir() + "/failed-write";
  fs::create_directories(dir);
  const std::string p = dir + "/keep.png";
  art::WriteImage(Image(4, 4, { 1, 0, 0, 1 }), p);
  const auto before = fs::file_size(p);
  // An empty image is refused before anything is written.
  EXPECT_THROW(art::WriteImage(Image(), p), art::Error);
  EXPECT_EQ(fs::file_size(p), before);
  EXPECT_EQ(CountTemps(dir), 0u);
}

// Writing onto a symbolic link replaced the link with a plain file and left the file it named as
// it was (a 'latest.png' pointing into a results folder); a shell's '>' writes through it. The
// replaced file keeps its permissions (it came back 0644 whatever it had been).
TEST(ImageIO, WritesThroughSymbolicLinksAndKeepsPermissions)
{
  const fs::path dir = fs::path(TempDir()) / "links";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  const fs::path real = dir / "results" / "run1.png";
  art::WriteImage(Image(4, 4, { 1, 0, 0, 1 }), real.string());
  fs::permissions(real, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
      fs::perms::group_write | fs::perms::others_read);
  const fs::path link = dir / "latest.png";
  fs::create_symlink("results/run1.png", link);
  art::WriteImage(Image(8, 2, { 0, 1, 0, 1 }), link.string());
  EXPECT_TRUE(fs::is_symlink(link));
  const Image back = art::ReadImage(real.string());
  EXPECT_EQ(back.Width(), 8);
  EXPECT_EQ(back.Height(), 2);
  EXPECT_EQ(fs::status(real).permissions() & fs::perms::group_write, fs::perms::group_write);
  EXPECT_EQ(CountTemps(dir.string()) + CountTemps((dir / "results").string()), 0u);
}

TEST(ImageIO, ErrorsNameTheFile)
{
  try
  {
    art::WriteImage(Image(2, 2), "/nonexistent-folder/x.png");
    FAIL() << "no error";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.png"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos);
  }
  // A file where the folder should be was called a folder that does not exist.
  const std::string plain = TempDir() + "/plain-file";
  std::ofstream(plain) << "x";
  try
  {
    art::WriteImage(Image(2, 2), plain + "/x.png");
    FAIL() << "no error";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("plain-file' is a file, not a folder"), std::string::npos) << e.what();
  }
  // A folder no file can be made in (root passes the access check in /sys) said
  // "cannot write image: OutOfDiskSpaceError", VTK's PNG writer's word for any failed open.
  // Only where the system itself refuses a file there: in a chroot without sysfs, /sys is a
  // plain folder.
  auto refusesFiles = [](const std::string& dir) {
    const std::string probe = dir + "/.adaptivert-write-probe";
    if (std::ofstream(probe))
    {
      std::remove(probe.c_str());
      return false;
    }
    return true;
  };
  if (std::filesystem::is_directory("/sys") && refusesFiles("/sys"))
  {
    try
    {
      art::WriteImage(Image(2, 2), "/sys/x.png");
      FAIL() << "no error";
    }
    catch (const art::Error& e)
    {
      const std::string what = e.what();
      EXPECT_TRUE(what.find("folder '/sys' is not writable") != std::string::npos ||
        what.find("cannot create a file in folder '/sys': ") != std::string::npos)
        << what;
    }
  }
  EXPECT_THROW(art::WriteImage(Image(2, 2), TempDir() + "/x.bmpx"), art::Error);
  EXPECT_THROW(art::ReadImage(TempDir() + "/missing.png"), art::Error);
  const std::string junk = TempDir() + "/junk.png";
  std::ofstream(junk) << "definitely not a png";
  EXPECT_THROW(art::ReadImage(junk), art::Error);
}

// Ctrl-C (or a kill) while a file is being written left its hidden temporary beside the target.
// A child process opens one, writes half of it and is interrupted; the target stays as it was.
TEST(ImageIO, InterruptedWriteLeavesNoTemp)
{
  const std::string dir = TempDir() + "/interrupted";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string target = dir + "/out.vtu";
  std::ofstream(target) << "the user's file";
  for (int sig : { SIGINT, SIGTERM })
  {
    struct sigaction now = {};
    sigaction(sig, nullptr, &now);
    if (now.sa_handler == SIG_IGN)
    {
      continue; // a background shell ignores SIGINT; the handler leaves that alone
    }
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
      art::AtomicFile f(target);
      std::ofstream(f.TempPath()) << "half a mesh";
      std::raise(sig);
      _exit(0); // not reached
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig);
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir))
    {
      ++files;
      EXPECT_EQ(e.path().filename(), "out.vtu");
    }
    EXPECT_EQ(files, 1u);
    std::ifstream in(target);
    std::string kept;
    std::getline(in, kept);
    EXPECT_EQ(kept, "the user's file");
  }
}
