#pragma once
// glm::vec3 <-> Python: any sequence of three numbers in (a tuple, a list, a numpy array), a
// tuple of three floats out.
#include <pybind11/pybind11.h>

#include <penumbra/core/math.h>

namespace pybind11::detail {

template <>
struct type_caster<glm::vec3> {
  PYBIND11_TYPE_CASTER(glm::vec3, const_name("tuple[float, float, float]"));

  bool load(handle source, bool convert) {
    if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
    const sequence items = reinterpret_borrow<sequence>(source);
    if (items.size() != 3) return false;
    for (size_t i = 0; i < 3; ++i) {
      make_caster<float> component;
      if (!component.load(items[i], convert)) return false;
      value[int(i)] = cast_op<float>(component);
    }
    return true;
  }

  static handle cast(const glm::vec3& v, return_value_policy, handle) {
    return make_tuple(v.x, v.y, v.z).release();
  }
};

}  // namespace pybind11::detail
