#include "scene/up_axis.h"

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra {

UpAxis parseUpAxis(const std::string& text) {
  if (text == "x") return UpAxis::X;
  if (text == "y") return UpAxis::Y;
  if (text == "z") return UpAxis::Z;
  throw Error(fmt::format("up axis '{}' must be x, y or z", text));
}

mat4 upAxisToY(UpAxis up) {
  // Columns are the images of the x, y and z axes.
  switch (up) {
    case UpAxis::X:
      return mat4(vec4(0, 1, 0, 0), vec4(-1, 0, 0, 0), vec4(0, 0, 1, 0), vec4(0, 0, 0, 1));
    case UpAxis::Z:
      return mat4(vec4(1, 0, 0, 0), vec4(0, 0, -1, 0), vec4(0, 1, 0, 0), vec4(0, 0, 0, 1));
    case UpAxis::Y:
      break;
  }
  return mat4(1.0f);
}

}  // namespace penumbra
