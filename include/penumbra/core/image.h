#pragma once
// A 2D array of pixels, row-major, row 0 at the top of the picture.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <penumbra/core/error.h>

namespace penumbra {

// std::allocator, except that value-less construction default-initialises: growing a vector of
// pixels with resize() then leaves trivial pixels uninitialised instead of zeroing them.
template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

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
  // For a producer that writes every pixel (a full-frame pass): no clearing pass over memory
  // that is overwritten anyway (8 MB per float buffer at 1920x1080). Pixels keep whatever they
  // held; read none before writing it.
  void resizeForOverwrite(int width, int height) {
    PENUMBRA_CHECK(width >= 0 && height >= 0, "image size {}x{} is negative", width, height);
    width_ = width;
    height_ = height;
    pixels_.resize(size_t(width) * size_t(height));
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
  std::vector<T, DefaultInitAllocator<T>> pixels_;
};

}  // namespace penumbra
