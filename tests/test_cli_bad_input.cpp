// Bad command lines and hostile image files given to the CLI (issue 10's fuzzing list): each
// ends in exit code 1 and a message that says what is wrong, never a silent default, an
// overwritten output or gigabytes allocated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_test_util.h"
#include "core/image_io.h"

namespace penumbra {
namespace test_cli_bad_input {

namespace fs = std::filesystem;

using testing::CliRun;

class CliBadInput : public testing::CliTest {};

void expectError(const CliRun& r, const std::string& mentions) {
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(mentions), std::string::npos) << r.err;
}

const std::string kTiny = "render spheres --width 16 --height 12 --quiet ";

// "--width 64abc" was called "not in range"; it is not a number at all.
TEST_F(CliBadInput, TrailingGarbageInANumberIsNamed) {
  expectError(run(kTiny + "--width 64abc"), "'64abc' is not a whole number");
  expectError(run(kTiny + "--height 9000"), "9000 is not in 1..8192");
  expectError(run(kTiny + "--threads 1e3"), "'1e3' is not a whole number");
}

// `-o ''` wrote out/<scene>.png; an empty name is a mistake.
TEST_F(CliBadInput, EmptyOutputNameIsRefused) {
  expectError(run(kTiny + "-o ''"), "--output is given an empty file name");
  expectError(run(kTiny + "-o a.png --stats ''"), "--stats is given an empty file name");
  EXPECT_FALSE(fs::exists(path("out")));
}

// `-o X --visibility-png X` silently overwrote the render with the visibility.
TEST_F(CliBadInput, TwoOutputsNamingOneFileAreRefused) {
  expectError(run(kTiny + "-o x.png --visibility-png x.png"),
              "-o 'x.png' and --visibility-png 'x.png' are the same file");
  expectError(run(kTiny + "-o x.png --visibility-png ./sub/../x.png"), "are the same file");
  EXPECT_FALSE(fs::exists(path("x.png")));  // refused before rendering
}

// --rays with --hard, or for a light of radius 0, was silently ignored (the oracle casts one
// ray per pixel): an error, and a warning naming the light.
TEST_F(CliBadInput, RaysThatCannotBeCastAreReported) {
  expectError(run(kTiny + "--technique reference --hard --rays 64"),
              "--rays has no effect with --hard");
  std::ofstream(path("point.json"))
      << R"({"meshes": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}],
             "lights": [{"center": [0, 5, 0]}], "settings": {"width": 16, "height": 12}})";
  const CliRun r = run("render point.json --technique reference --rays 64 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --rays is unused for light 0: its radius is 0"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(run(kTiny + "--technique reference --rays 4").err, "");  // spheres: a soft light
}

// A 74-byte PNG whose header claims 100000 x 100000 pixels: 4.1 GB were allocated (the size
// wrapped in 32 bits) before libpng refused. The size is checked first.
TEST_F(CliBadInput, ComparePngWithHugeHeaderIsRefusedBeforeAllocating) {
  writePngGray(path("small.png"), Image<float>(2, 2, 0.5f));
  std::string bytes = testing::slurp(path("small.png"));
  ASSERT_GT(bytes.size(), 24u);
  // IHDR width and height, big-endian, at bytes 16..23, then the chunk's CRC over bytes 12..28
  // (type and data) at 29..32, so that libpng accepts the header.
  auto put32 = [&](size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = char((v >> (24 - 8 * i)) & 0xff);
  };
  put32(16, 100000);
  put32(20, 100000);
  uint32_t crc = 0xffffffffu;  // CRC-32 (ISO 3309), as PNG chunks use
  for (size_t i = 12; i < 29; ++i) {
    crc ^= uint8_t(bytes[i]);
    for (int b = 0; b < 8; ++b) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  put32(29, ~crc);
  std::ofstream(path("huge.png"), std::ios::binary) << bytes;
  expectError(run("compare huge.png small.png"),
              "cannot read PNG 'huge.png': 100000x100000 pixels is more than the limit");
}

// An image full of NaN printed MAE 0 and exited 0: now NaN is reported and the comparison
// fails, whatever the tolerance.
TEST_F(CliBadInput, CompareWithNaNFails) {
  writeExr(path("nan.exr"), Image<float>(4, 4, NAN));
  writeExr(path("zero.exr"), Image<float>(4, 4, 0.0f));
  const CliRun r = run("compare nan.exr zero.exr --tolerance 1000");
  expectError(r, "16 of 16 pixels are NaN or infinite");
  EXPECT_NE(r.out.find("MAE nan"), std::string::npos) << r.out;
  const CliRun json = run("compare nan.exr zero.exr --json");
  expectError(json, "NaN or infinite");
  EXPECT_NE(json.out.find("\"count_nonfinite\": 16"), std::string::npos) << json.out;
  EXPECT_EQ(run("compare zero.exr zero.exr").exit_code, 0);
}

}  // namespace test_cli_bad_input
}  // namespace penumbra
