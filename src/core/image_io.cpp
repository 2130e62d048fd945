#include "core/image_io.h"

#include <png.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "core/output_file.h"
#include "core/path_extension.h"

namespace penumbra {
namespace fs = std::filesystem;

float srgbEncode(float linear) {
  // IEC 61966-2-1: a linear toe below 0.0031308, a 1/2.4 power above.
  if (linear <= 0.0031308f) return 12.92f * linear;
  return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbDecode(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

uint8_t unitToByte(float value) {
  if (!(value > 0.0f)) return 0;  // also NaN
  if (value >= 1.0f) return 255;
  return uint8_t(std::floor(value * 255.0f + 0.5f));
}

uint8_t linearToSrgb8(float linear) {
  // Code k + 1 begins where the curve crosses (k + 0.5) / 255, so counting the crossings below
  // `linear` rounds exactly like round(255 * srgbEncode(linear)) without a pow per channel.
  static const std::array<float, 255> kThresholds = [] {
    std::array<float, 255> t{};
    for (size_t k = 0; k < t.size(); ++k) t[k] = srgbDecode((float(k) + 0.5f) / 255.0f);
    return t;
  }();
  if (!(linear > 0.0f)) return 0;  // also NaN
  return uint8_t(std::upper_bound(kThresholds.begin(), kThresholds.end(), linear) -
                 kThresholds.begin());
}

void createParentDirectories(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  PENUMBRA_CHECK(!ec, "cannot create folder '{}' for '{}': {}", parent.string(), path,
                 ec.message());
}

namespace {

void checkWritable(const std::string& path, int width, int height) {
  PENUMBRA_CHECK(!path.empty(), "output image path is empty");
  PENUMBRA_CHECK(width > 0 && height > 0, "cannot write '{}': the image is empty ({}x{})", path,
                 width, height);
}

void checkReadable(const std::string& path) {
  std::error_code ec;
  PENUMBRA_CHECK(fs::exists(path, ec), "image file '{}' does not exist", path);
  PENUMBRA_CHECK(!fs::is_directory(path, ec), "image file '{}' is a folder", path);
}

// `format`: PNG_FORMAT_GRAY or PNG_FORMAT_RGB, 8 bits per channel.
void writePng8(const std::string& path, int width, int height, uint32_t format,
               const uint8_t* bytes) {
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = format;
  // Encoded in memory first (a call without a buffer measures it), then written whole by
  // writeFileAtomically: libpng's own file writer leaves a truncated file on a full disk.
  png_alloc_size_t size = 0;
  int ok = png_image_write_to_memory(&image, nullptr, &size, 0, bytes, 0, nullptr);
  std::vector<uint8_t> encoded(ok ? size : 0);
  if (ok) ok = png_image_write_to_memory(&image, encoded.data(), &size, 0, bytes, 0, nullptr);
  const std::string message = image.message;
  png_image_free(&image);
  PENUMBRA_CHECK(ok != 0, "cannot write PNG '{}': {}", path, message);
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), size),
                      "PNG");
}

// Larger images are refused before their pixels are allocated: a 74-byte PNG can claim
// 100000x100000 pixels. The renderer's largest image is 8192x8192.
constexpr uint64_t kMaxReadPixels = uint64_t(8192) * 8192;

void checkReadSize(const std::string& path, const char* kind, uint64_t width, uint64_t height) {
  PENUMBRA_CHECK(width > 0 && height > 0, "cannot read {} '{}': its size is {}x{}", kind, path,
                 width, height);
  PENUMBRA_CHECK(width <= kMaxReadPixels && height <= kMaxReadPixels &&
                     width * height <= kMaxReadPixels,
                 "cannot read {} '{}': {}x{} pixels is more than the limit of {} pixels "
                 "(8192x8192)",
                 kind, path, width, height, kMaxReadPixels);
}

// Reads a PNG into 8-bit `format` (PNG_FORMAT_GRAY or PNG_FORMAT_RGB). libpng's simplified
// API converts bit depth, palette and colour type; alpha is composited on black.
std::vector<uint8_t> readPng8(const std::string& path, uint32_t format, int& width,
                              int& height) {
  checkReadable(path);
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0) {
    const std::string message = image.message;
    png_image_free(&image);
    throw Error(fmt::format("cannot read PNG '{}': {}", path, message));
  }
  if (image.width == 0 || image.height == 0 ||
      uint64_t(image.width) * image.height > kMaxReadPixels) {
    png_image_free(&image);
    checkReadSize(path, "PNG", image.width, image.height);
  }
  image.format = format;
  std::vector<uint8_t> bytes(PNG_IMAGE_SIZE(image));
  const png_color black{0, 0, 0};
  if (png_image_finish_read(&image, &black, bytes.data(), 0, nullptr) == 0) {
    const std::string message = image.message;
    png_image_free(&image);
    throw Error(fmt::format("cannot read PNG '{}': {}", path, message));
  }
  width = int(image.width);
  height = int(image.height);
  png_image_free(&image);
  return bytes;
}

// Frees tinyexr's allocations on every path out of readExr.
struct ExrHeaderGuard {
  EXRHeader header;
  bool parsed = false;
  ExrHeaderGuard() { InitEXRHeader(&header); }
  ~ExrHeaderGuard() {
    if (parsed) FreeEXRHeader(&header);
  }
};
struct ExrImageGuard {
  EXRImage image;
  bool loaded = false;
  ExrImageGuard() { InitEXRImage(&image); }
  ~ExrImageGuard() {
    if (loaded) FreeEXRImage(&image);
  }
};

std::string takeExrError(const char* err) {
  std::string message = err ? err : "unknown error";
  if (err) FreeEXRErrorMessage(err);
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  return message;
}

float exrSample(const EXRImage& image, const EXRHeader& header, int channel, size_t i) {
  switch (header.pixel_types[channel]) {
    case TINYEXR_PIXELTYPE_FLOAT:
      return reinterpret_cast<const float*>(image.images[channel])[i];
    case TINYEXR_PIXELTYPE_UINT:
      return float(reinterpret_cast<const uint32_t*>(image.images[channel])[i]);
    default:
      throw Error("unexpected EXR pixel type");  // half was requested as float on load
  }
}

}  // namespace

void writePng(const std::string& path, const Image<vec3>& linear) {
  checkWritable(path, linear.width(), linear.height());
  std::vector<uint8_t> bytes(linear.size() * 3);
  for (size_t i = 0; i < linear.size(); ++i) {
    for (int c = 0; c < 3; ++c) bytes[i * 3 + size_t(c)] = linearToSrgb8(linear[i][c]);
  }
  writePng8(path, linear.width(), linear.height(), PNG_FORMAT_RGB, bytes.data());
}

void writePngGray(const std::string& path, const Image<float>& values) {
  checkWritable(path, values.width(), values.height());
  std::vector<uint8_t> bytes(values.size());
  for (size_t i = 0; i < values.size(); ++i) bytes[i] = unitToByte(values[i]);
  writePng8(path, values.width(), values.height(), PNG_FORMAT_GRAY, bytes.data());
}

void writePngRgb8(const std::string& path, const Image<glm::u8vec3>& rgb) {
  checkWritable(path, rgb.width(), rgb.height());
  static_assert(sizeof(glm::u8vec3) == 3, "u8vec3 must be packed RGB bytes");
  writePng8(path, rgb.width(), rgb.height(), PNG_FORMAT_RGB,
            reinterpret_cast<const uint8_t*>(rgb.data()));
}

Image<vec3> readPng(const std::string& path) {
  int width = 0;
  int height = 0;
  const std::vector<uint8_t> bytes = readPng8(path, PNG_FORMAT_RGB, width, height);
  std::array<float, 256> decode{};
  for (int v = 0; v < 256; ++v) decode[size_t(v)] = srgbDecode(float(v) / 255.0f);
  Image<vec3> out(width, height);
  for (size_t i = 0; i < out.size(); ++i) {
    out[i] = vec3(decode[bytes[i * 3]], decode[bytes[i * 3 + 1]], decode[bytes[i * 3 + 2]]);
  }
  return out;
}

Image<float> readPngGray(const std::string& path) {
  int width = 0;
  int height = 0;
  const std::vector<uint8_t> bytes = readPng8(path, PNG_FORMAT_GRAY, width, height);
  Image<float> out(width, height);
  for (size_t i = 0; i < out.size(); ++i) out[i] = float(bytes[i]) / 255.0f;
  return out;
}

bool isGrayPng(const std::string& path) {
  checkReadable(path);
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  const int ok = png_image_begin_read_from_file(&image, path.c_str());
  const std::string message = ok ? "" : image.message;
  const uint32_t format = image.format;
  png_image_free(&image);
  PENUMBRA_CHECK(ok != 0, "cannot read PNG '{}': {}", path, message);
  return (format & PNG_FORMAT_FLAG_COLOR) == 0;
}

void writeExr(const std::string& path, const Image<float>& values) {
  checkWritable(path, values.width(), values.height());
  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage image;
  InitEXRImage(&image);

  // tinyexr only reads these arrays, so they can live on the stack (no FreeEXR* calls).
  EXRChannelInfo channel;
  std::memset(&channel, 0, sizeof(channel));
  std::strncpy(channel.name, "Y", sizeof(channel.name) - 1);
  int pixel_type = TINYEXR_PIXELTYPE_FLOAT;
  int requested_type = TINYEXR_PIXELTYPE_FLOAT;  // float32 on disk: exact round trip
  header.num_channels = 1;
  header.channels = &channel;
  header.pixel_types = &pixel_type;
  header.requested_pixel_types = &requested_type;
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

  const float* plane = values.data();
  image.num_channels = 1;
  image.width = values.width();
  image.height = values.height();
  image.images = reinterpret_cast<unsigned char**>(const_cast<float**>(&plane));

  // Encoded in memory, then written whole: tinyexr's file writer does not check its writes
  // (a full disk gave 0-byte files and exit code 0).
  const char* err = nullptr;
  unsigned char* encoded = nullptr;
  const size_t size = SaveEXRImageToMemory(&image, &header, &encoded, &err);
  if (size == 0 || encoded == nullptr) {
    throw Error(fmt::format("cannot write EXR '{}': {}", path, takeExrError(err)));
  }
  const std::unique_ptr<unsigned char, decltype(&std::free)> owned(encoded, &std::free);
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(encoded), size), "EXR");
}

Image<float> readExr(const std::string& path) {
  checkReadable(path);
  EXRVersion version;
  PENUMBRA_CHECK(ParseEXRVersionFromFile(&version, path.c_str()) == TINYEXR_SUCCESS,
                 "'{}' is not an OpenEXR file", path);
  PENUMBRA_CHECK(!version.multipart && !version.non_image,
                 "EXR '{}' is multi-part or deep; only single-part scanline files are read",
                 path);

  ExrHeaderGuard h;
  const char* err = nullptr;
  if (ParseEXRHeaderFromFile(&h.header, &version, path.c_str(), &err) != TINYEXR_SUCCESS) {
    throw Error(fmt::format("cannot read EXR '{}': {}", path, takeExrError(err)));
  }
  h.parsed = true;
  const EXRBox2i& window = h.header.data_window;
  checkReadSize(path, "EXR", uint64_t(int64_t(window.max_x) - window.min_x + 1),
                uint64_t(int64_t(window.max_y) - window.min_y + 1));
  PENUMBRA_CHECK(!h.header.tiled, "EXR '{}' is tiled; only scanline files are read", path);
  PENUMBRA_CHECK(h.header.num_channels > 0, "EXR '{}' has no channels", path);
  for (int c = 0; c < h.header.num_channels; ++c) {
    if (h.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
      h.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    }
  }

  ExrImageGuard im;
  if (LoadEXRImageFromFile(&im.image, &h.header, path.c_str(), &err) != TINYEXR_SUCCESS) {
    throw Error(fmt::format("cannot read EXR '{}': {}", path, takeExrError(err)));
  }
  im.loaded = true;
  PENUMBRA_CHECK(im.image.images != nullptr && im.image.width > 0 && im.image.height > 0,
                 "EXR '{}' holds no scanline pixels", path);

  auto find = [&](const char* name) {
    for (int c = 0; c < h.header.num_channels; ++c) {
      if (std::strcmp(h.header.channels[c].name, name) == 0) return c;
    }
    return -1;
  };
  const int y = find("Y");
  const int r = find("R");
  const int g = find("G");
  const int b = find("B");
  PENUMBRA_CHECK(y >= 0 || (r >= 0 && g >= 0 && b >= 0) || h.header.num_channels == 1,
                 "EXR '{}' has {} channels but no Y channel and no R, G, B channels", path,
                 h.header.num_channels);

  Image<float> out(im.image.width, im.image.height);
  for (size_t i = 0; i < out.size(); ++i) {
    if (y >= 0) {
      out[i] = exrSample(im.image, h.header, y, i);
    } else if (r >= 0 && g >= 0 && b >= 0) {
      out[i] = (exrSample(im.image, h.header, r, i) + exrSample(im.image, h.header, g, i) +
                exrSample(im.image, h.header, b, i)) /
               3.0f;
    } else {
      out[i] = exrSample(im.image, h.header, 0, i);
    }
  }
  return out;
}

ImageFile readImageFile(const std::string& path) {
  const std::string ext = lowerExtension(path);
  ImageFile file;
  if (ext == ".exr") {
    file.gray = readExr(path);
  } else if (ext == ".png") {
    if (isGrayPng(path)) {
      file.gray = readPngGray(path);
    } else {
      file.is_color = true;
      file.color = readPng(path);
    }
  } else {
    throw Error(fmt::format("'{}' is neither an .exr nor a .png file", path));
  }
  return file;
}

std::string indexedOutputPath(const std::string& path, size_t index) {
  if (index == 0) return path;
  const fs::path p(path);
  fs::path name = p.stem();
  name += fmt::format(".{}", index);
  name += p.extension();
  return (p.parent_path() / name).string();
}

}  // namespace penumbra
