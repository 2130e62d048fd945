#pragma once
// Image files: PNG for people (libpng), single-channel float32 EXR for buffers that must keep
// their exact values (tinyexr). Writers create the output's parent folders. Every error throws
// penumbra::Error naming the file.
//
// Conventions: Image<vec3> colours are linear RGB; writePng encodes them with the sRGB curve
// (IEC 61966-2-1) and readPng decodes it. Gray PNGs hold data (visibility), not colour: value v
// in [0, 1] is stored as round(255 v) with no transfer curve, and read back as stored / 255.
#include <cstdint>
#include <string>

#include <penumbra/core/image.h>
#include <penumbra/core/math.h>

namespace penumbra {

// The sRGB transfer curve on [0, 1] (no clamping; negative in, negative out).
float srgbEncode(float linear);
float srgbDecode(float encoded);
// Linear value -> 8-bit sRGB code, clamped to [0, 1] first; NaN gives 0.
uint8_t linearToSrgb8(float linear);
// Value in [0, 1] -> round(255 v), clamped; NaN gives 0 (gray data maps, no transfer curve).
uint8_t unitToByte(float value);

void writePng(const std::string& path, const Image<vec3>& linear);
void writePngGray(const std::string& path, const Image<float>& values);
// Already display-ready 8-bit RGB (heat maps), written as is.
void writePngRgb8(const std::string& path, const Image<glm::u8vec3>& rgb);

// Any PNG (8 or 16 bit, gray, palette, alpha) -> linear RGB; alpha is dropped.
Image<vec3> readPng(const std::string& path);
// Any PNG -> gray stored / 255 (colour files are converted to gray by libpng).
Image<float> readPngGray(const std::string& path);
bool isGrayPng(const std::string& path);

// One float32 channel named "Y", ZIP-compressed (lossless: read back bit for bit).
void writeExr(const std::string& path, const Image<float>& values);
// The "Y" channel of an EXR; else the mean of R, G, B; else its only channel. Half and uint
// channels are converted to float. Tiled, multi-part and deep files are rejected.
Image<float> readExr(const std::string& path);

// An image file read for comparison: EXR and gray PNG as gray values, colour PNG as linear RGB.
struct ImageFile {
  bool is_color = false;
  Image<float> gray;   // when !is_color
  Image<vec3> color;   // when is_color
  int width() const { return is_color ? color.width() : gray.width(); }
  int height() const { return is_color ? color.height() : gray.height(); }
};
// By extension (.exr, .png, case-insensitive); anything else is an error.
ImageFile readImageFile(const std::string& path);

// Output path of light `index` when a frame has several lights: light 0 keeps `path`, light i
// gets ".i" before the extension ("vis.exr" -> "vis.1.exr").
std::string indexedOutputPath(const std::string& path, size_t index);

// Creates the folders `path` will be written into; throws naming the folder on failure.
void createParentDirectories(const std::string& path);

}  // namespace penumbra
