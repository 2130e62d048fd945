#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace penumbra {
namespace test_output_png {

namespace fs = std::filesystem;

// A folder of this test's own (ctest may run tests of this binary in parallel processes).
fs::path testDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(::testing::TempDir()) /
                       fmt::format("penumbra_{}_{}_{}", info->test_suite_name(), info->name(),
                                   ::getpid());
  fs::remove_all(dir);
  return dir;
}

// The sRGB curve's known codes; a gamma-2.2 approximation or a missing curve would miss them.
TEST(OutputSrgb, KnownCodes) {
  EXPECT_EQ(linearToSrgb8(0.0f), 0);
  EXPECT_EQ(linearToSrgb8(1.0f), 255);
  EXPECT_EQ(linearToSrgb8(0.5f), 188);
  EXPECT_EQ(linearToSrgb8(0.2158605f), 128);  // sRGB 128/255 decodes to 0.2158605
  EXPECT_EQ(linearToSrgb8(0.001f), 3);        // linear toe: 12.92 * 0.001 * 255 = 3.29
  EXPECT_EQ(linearToSrgb8(-1.0f), 0);
  EXPECT_EQ(linearToSrgb8(7.0f), 255);
  EXPECT_EQ(linearToSrgb8(NAN), 0);
}

// The table-driven 8-bit encoder must round like the curve itself: a shifted threshold would
// band dark gradients. Sweeps [0, 1] densely, with extra density in the steep dark end; exact
// half-step ties may round either way.
TEST(OutputSrgb, EightBitMatchesTheCurve) {
  int mismatches = 0;
  for (int i = 0; i <= 200000; ++i) {
    const float v = i < 100000 ? float(i) * 1e-7f : float(i - 100000) / 100000.0f;
    const float scaled = srgbEncode(v) * 255.0f;
    const int direct = int(std::floor(scaled + 0.5f));
    // Within float rounding of a half step either neighbour is right.
    const bool tie = std::abs(scaled - std::floor(scaled) - 0.5f) < 1e-4f;
    if (int(linearToSrgb8(v)) != direct && !tie) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0);
}

// Encode and decode must be inverses, or reading a PNG back would shift every colour.
TEST(OutputSrgb, DecodeInvertsEncode) {
  for (float v = 0.0f; v <= 1.0f; v += 0.01f) {
    EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-5f) << v;
  }
  EXPECT_NEAR(srgbDecode(128.0f / 255.0f), 0.2158605f, 1e-6f);
}

// Gray data maps have no transfer curve: 0.5 is stored as 128, not 188.
TEST(OutputSrgb, UnitToByteIsLinear) {
  EXPECT_EQ(unitToByte(0.5f), 128);
  EXPECT_EQ(unitToByte(0.25f), 64);
  EXPECT_EQ(unitToByte(1.5f), 255);
  EXPECT_EQ(unitToByte(-0.5f), 0);
}

// Colour PNG round trip: within half an 8-bit sRGB step, in the folder the writer created.
TEST(OutputPng, ColorRoundTripCreatesFolders) {
  const fs::path dir = testDir();
  const std::string path = (dir / "nested" / "deeper" / "color.png").string();
  Image<vec3> image(7, 5);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      image.at(x, y) = vec3(x / 6.0f, y / 4.0f, (x * y) / 24.0f);
    }
  }
  writePng(path, image);
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(isGrayPng(path));
  const Image<vec3> back = readPng(path);
  ASSERT_EQ(back.width(), 7);
  ASSERT_EQ(back.height(), 5);
  for (size_t i = 0; i < image.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      // Compare in the encoded domain, where quantisation is uniform.
      EXPECT_NEAR(srgbEncode(back[i][c]), srgbEncode(image[i][c]), 0.5f / 255.0f + 1e-6f);
    }
  }
  // Row 0 is the top: a flipped writer would swap these.
  EXPECT_LT(back.at(0, 0).y, back.at(0, 4).y);
  fs::remove_all(dir);
}

// Gray round trip is exact for values on the 8-bit grid; rows and columns keep their place.
TEST(OutputPng, GrayRoundTrip) {
  const fs::path dir = testDir();
  const std::string path = (dir / "gray.png").string();
  Image<float> image(16, 3);
  for (size_t i = 0; i < image.size(); ++i) image[i] = float(i * 5 % 256) / 255.0f;
  writePngGray(path, image);
  EXPECT_TRUE(isGrayPng(path));
  const Image<float> back = readPngGray(path);
  ASSERT_EQ(back.width(), 16);
  ASSERT_EQ(back.height(), 3);
  for (size_t i = 0; i < image.size(); ++i) EXPECT_FLOAT_EQ(back[i], image[i]) << i;
  fs::remove_all(dir);
}

TEST(OutputPng, Rgb8WrittenAsIs) {
  const fs::path dir = testDir();
  const std::string path = (dir / "rgb8.png").string();
  Image<glm::u8vec3> image(2, 2);
  image.at(0, 0) = {255, 0, 0};
  image.at(1, 0) = {0, 128, 0};
  image.at(0, 1) = {0, 0, 7};
  image.at(1, 1) = {1, 2, 3};
  writePngRgb8(path, image);
  const Image<vec3> back = readPng(path);
  // readPng decodes sRGB, so encode again to get the stored bytes.
  for (size_t i = 0; i < image.size(); ++i) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(linearToSrgb8(back[i][c]), image[i][c]) << i;
  }
  fs::remove_all(dir);
}

// Errors name the file so a user knows which argument is wrong.
TEST(OutputPng, ErrorsNameTheFile) {
  const fs::path dir = testDir();
  const std::string missing = (dir / "missing.png").string();
  try {
    readPng(missing);
    FAIL() << "reading a missing PNG did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  fs::create_directories(dir);
  const std::string garbage = (dir / "garbage.png").string();
  std::ofstream(garbage) << "this is not a PNG";
  try {
    readPngGray(garbage);
    FAIL() << "reading a non-PNG did not throw";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(garbage), std::string::npos) << e.what();
  }
  EXPECT_THROW(writePng((dir / "empty.png").string(), Image<vec3>()), Error);
  // A file where a folder should be: the writer cannot create the folder.
  EXPECT_THROW(writePng((fs::path(garbage) / "x.png").string(), Image<vec3>(1, 1)), Error);
  fs::remove_all(dir);
}

// Per-light outputs must not overwrite each other, and light 0 keeps the name the user gave.
TEST(OutputPaths, IndexedOutputPath) {
  EXPECT_EQ(indexedOutputPath("vis.exr", 0), "vis.exr");
  EXPECT_EQ(indexedOutputPath("vis.exr", 1), "vis.1.exr");
  EXPECT_EQ(indexedOutputPath("out/a.b/vis.png", 12), "out/a.b/vis.12.png");
  EXPECT_EQ(indexedOutputPath("noext", 2), "noext.2");
}

}  // namespace test_output_png
}  // namespace penumbra
