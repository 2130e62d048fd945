#pragma once
// A 2D array of pixels, row-major, row 0 at the top of the picture.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/error.h"

namespace penumbra {

template <typename T>
class Image {
 public:
  Image() = default;
  Image(int width, int height, T fill = T{}) { resize(width, height, fill); }

  void resize(int width, int height, T fill = T{}) {
    PENUMBRA_CHECK(width >= 0 && height >= 0, "image size {}x{} is negative", width, height);
    width_ = width;
    height_ = height;
    pixels_.assign(size_t(width) * size_t(height), fill);
  }
  void fill(T value) { std::fill(pixels_.begin(), pixels_.end(), value); }

  int width() const { return width_; }
  int height() const { return height_; }
  size_t size() const { return pixels_.size(); }
  bool empty() const { return pixels_.empty(); }

  T& at(int x, int y) { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  const T& at(int x, int y) const { return pixels_[size_t(y) * size_t(width_) + size_t(x)]; }
  T* row(int y) { return pixels_.data() + size_t(y) * size_t(width_); }
  const T* row(int y) const { return pixels_.data() + size_t(y) * size_t(width_); }
  T* data() { return pixels_.data(); }
  const T* data() const { return pixels_.data(); }
  T& operator[](size_t i) { return pixels_[i]; }
  const T& operator[](size_t i) const { return pixels_[i]; }

  bool operator==(const Image& o) const {
    return width_ == o.width_ && height_ == o.height_ && pixels_ == o.pixels_;
  }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<T> pixels_;
};

}  // namespace penumbra
