// Image comparison with the CLI's metrics (penumbra compare) and the library's image readers.
#include <optional>
#include <string>

#include "bindings.h"

namespace penumbra::python {

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

Image<float> grayImage(const FloatArray& a, const char* what) {
  PENUMBRA_CHECK(a.ndim() == 2, "{}: expected an H x W array, got {} dimensions", what, a.ndim());
  Image<float> image(int(a.shape(1)), int(a.shape(0)));
  std::copy(a.data(), a.data() + a.size(), image.data());
  return image;
}

Image<vec3> colorImage(const FloatArray& a, const char* what) {
  PENUMBRA_CHECK(a.ndim() == 3 && a.shape(2) == 3, "{}: expected an H x W x 3 array", what);
  Image<vec3> image(int(a.shape(1)), int(a.shape(0)));
  std::copy(a.data(), a.data() + a.size(), reinterpret_cast<float*>(image.data()));
  return image;
}

// Pixels where the mask is non-zero; a float mask is a depth buffer (render's depth, or
// read_image of a --depth EXR), whose covered pixels are depth > 0, as `compare --mask` takes.
Image<uint8_t> maskImage(const FloatArray& mask) {
  const Image<float> values = grayImage(mask, "mask");
  Image<uint8_t> covered(values.width(), values.height());
  for (size_t i = 0; i < values.size(); ++i) covered[i] = values[i] > 0.0f ? 1 : 0;
  return covered;
}

py::dict differenceDict(const ImageDifference& d) {
  py::dict out;
  out["pixels"] = d.pixels;
  out["mae"] = d.mae;
  out["rmse"] = d.rmse;
  out["max_error"] = d.max_error;
  out["count_over_tolerance"] = d.count_over_tolerance;
  out["fraction_over_tolerance"] = d.fraction_over_tolerance;
  out["count_nonfinite"] = d.count_nonfinite;
  return out;
}

py::array ownedArray(Image<float> image) {
  auto* owned = new Image<float>(std::move(image));
  py::capsule owner(owned, [](void* p) { delete static_cast<Image<float>*>(p); });
  return py::array_t<float>({owned->height(), owned->width()},
                            {ssize_t(owned->width() * sizeof(float)), ssize_t(sizeof(float))},
                            owned->data(), owner);
}

py::array ownedArray(Image<vec3> image) {
  auto* owned = new Image<vec3>(std::move(image));
  py::capsule owner(owned, [](void* p) { delete static_cast<Image<vec3>*>(p); });
  return py::array_t<float>(
      {owned->height(), owned->width(), 3},
      {ssize_t(owned->width() * sizeof(vec3)), ssize_t(sizeof(vec3)), ssize_t(sizeof(float))},
      reinterpret_cast<const float*>(owned->data()), owner);
}

}  // namespace

void bindImages(py::module_& m) {
  m.def(
      "_compare",
      [](const FloatArray& a, const FloatArray& b, const std::optional<FloatArray>& mask,
         double tolerance) {
        std::optional<Image<uint8_t>> covered;
        if (mask) covered = maskImage(*mask);
        const Image<uint8_t>* mask_pointer = covered ? &*covered : nullptr;
        PENUMBRA_CHECK(a.ndim() == b.ndim(), "compare: a has {} dimensions, b {}", a.ndim(), b.ndim());
        if (a.ndim() == 3) {
          return differenceDict(
              compareImages(colorImage(a, "a"), colorImage(b, "b"), tolerance, mask_pointer));
        }
        return differenceDict(
            compareImages(grayImage(a, "a"), grayImage(b, "b"), tolerance, mask_pointer));
      },
      py::arg("a"), py::arg("b"), py::arg("mask"), py::arg("tolerance"));
  m.def(
      "read_image",
      [](const std::string& path) -> py::array {
        ImageFile file = readImageFile(path);
        if (file.is_color) return ownedArray(std::move(file.color));
        return ownedArray(std::move(file.gray));
      },
      py::arg("path"),
      "An EXR or PNG file as compare reads it: EXR and gray PNG as H x W float32 values, colour "
      "PNG as H x W x 3 linear RGB.");
  m.def(
      "read_exr", [](const std::string& path) { return ownedArray(readExr(path)); },
      py::arg("path"),
      "A float EXR's 'Y' channel (else the mean of R, G, B, else its only channel), H x W "
      "float32, bit for bit as written.");
}

}  // namespace penumbra::python
