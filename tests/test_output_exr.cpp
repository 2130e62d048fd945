#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace penumbra {
namespace test_output_exr {

namespace fs = std::filesystem;

fs::path testDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) /
                       fmt::format("penumbra_{}_{}_{}", info->test_suite_name(), info->name(),
                                   ::getpid());
  fs::remove_all(dir);
  return dir;
}

// EXR is where visibility and depth are kept for comparison: the round trip must be bit-exact
// (a half-float or lossy file would put error into every comparison), and wide enough to keep
// sizes above the uncompressed-small-image path of tinyexr.
TEST(OutputExr, RoundTripIsBitExact) {
  const fs::path dir = testDir();
  const std::string path = (dir / "sub" / "values.exr").string();
  Image<float> image(37, 21);
  for (size_t i = 0; i < image.size(); ++i) {
    image[i] = std::sin(float(i) * 0.37f) * 1e-3f + float(i % 7) / 7.0f;
  }
  image[0] = 0.0f;
  image[1] = 1.0f;
  image[2] = 1.0f / 3.0f;
  image[3] = -2.5e-8f;
  image[4] = 65504.0f * 4.0f;  // beyond half precision
  writeExr(path, image);
  const Image<float> back = readExr(path);
  ASSERT_EQ(back.width(), image.width());
  ASSERT_EQ(back.height(), image.height());
  EXPECT_EQ(std::memcmp(back.data(), image.data(), image.size() * sizeof(float)), 0);
  fs::remove_all(dir);
}

TEST(OutputExr, TinyImageRoundTrip) {
  const fs::path dir = testDir();
  const std::string path = (dir / "tiny.exr").string();
  Image<float> image(2, 1);
  image[0] = 0.25f;
  image[1] = 0.75f;
  writeExr(path, image);
  EXPECT_TRUE(readExr(path) == image);
  fs::remove_all(dir);
}

TEST(OutputExr, ErrorsNameTheFile) {
  const fs::path dir = testDir();
  const std::string missing = (dir / "missing.exr").string();
  try {
    readExr(missing);
    FAIL() << "reading a missing EXR did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  fs::create_directories(dir);
  const std::string garbage = (dir / "garbage.exr").string();
  std::ofstream(garbage) << "definitely not OpenEXR";
  try {
    readExr(garbage);
    FAIL() << "reading a non-EXR did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(garbage), std::string::npos) << e.what();
  }
  EXPECT_THROW(writeExr((dir / "empty.exr").string(), Image<float>()), Error);
  fs::remove_all(dir);
}

// `compare` reads whatever it is given through readImageFile: EXR and gray PNG as gray values,
// colour PNG as colour; other extensions are refused rather than guessed.
TEST(OutputImageFile, ReadsByExtension) {
  const fs::path dir = testDir();
  Image<float> gray(3, 2, 0.5f);
  writeExr((dir / "a.EXR").string(), gray);
  writePngGray((dir / "b.png").string(), gray);
  writePng((dir / "c.png").string(), Image<vec3>(3, 2, vec3(0.5f)));
  const ImageFile a = readImageFile((dir / "a.EXR").string());
  EXPECT_FALSE(a.is_color);
  EXPECT_EQ(a.gray[0], 0.5f);
  const ImageFile b = readImageFile((dir / "b.png").string());
  EXPECT_FALSE(b.is_color);
  EXPECT_NEAR(b.gray[0], 0.5f, 0.51f / 255.0f + 1e-6f);
  const ImageFile c = readImageFile((dir / "c.png").string());
  EXPECT_TRUE(c.is_color);
  EXPECT_EQ(c.width(), 3);
  EXPECT_EQ(c.height(), 2);
  EXPECT_NEAR(c.color[0].x, 0.5f, 0.01f);
  EXPECT_THROW(readImageFile((dir / "d.jpg").string()), Error);
  fs::remove_all(dir);
}

}  // namespace test_output_exr
}  // namespace penumbra
