#include "shadows/technique.h"

#include "core/error.h"
#include "shadows/reference/reference.h"
#include "shadows/volume/shadow_volume.h"
#include "shadows/wedge/wedge_technique.h"

namespace penumbra {

TechniqueResult renderShadows(const TechniqueOptions& options, const Scene& scene,
                              const Light& light, const View& view, const EyeBuffers& eye) {
  PENUMBRA_CHECK(eye.depth.width() == view.width && eye.depth.height() == view.height,
                 "eye buffers are {}x{} but the view is {}x{}", eye.depth.width(),
                 eye.depth.height(), view.width, view.height);
  switch (options.kind) {
    case TechniqueKind::Reference:
      return renderReference(options, scene, light, view, eye);
    case TechniqueKind::ShadowVolume:
      return renderShadowVolume(options, scene, light, view, eye);
    case TechniqueKind::Wedge2002:
    case TechniqueKind::WedgeThreePass:
    case TechniqueKind::WedgeSinglePass:
      return renderWedges(options, scene, light, view, eye);
  }
  throw Error("unknown technique");
}

namespace {
struct NamedKind {
  const char* name;
  TechniqueKind kind;
};
constexpr NamedKind kNames[] = {
    {"reference", TechniqueKind::Reference},
    {"volume", TechniqueKind::ShadowVolume},
    {"wedge-2002", TechniqueKind::Wedge2002},
    {"wedge-3pass", TechniqueKind::WedgeThreePass},
    {"wedge-1pass", TechniqueKind::WedgeSinglePass},
};
}  // namespace

std::string techniqueName(TechniqueKind kind) {
  for (const auto& n : kNames)
    if (n.kind == kind) return n.name;
  return "unknown";
}

TechniqueKind parseTechniqueName(const std::string& name) {
  for (const auto& n : kNames)
    if (name == n.name) return n.kind;
  std::string known;
  for (const auto& n : kNames) known += std::string(known.empty() ? "" : ", ") + n.name;
  throw Error(fmt::format("unknown technique '{}' (known: {})", name, known));
}

std::string cullModeName(CullMode mode) {
  switch (mode) {
    case CullMode::None: return "none";
    case CullMode::ZMax: return "zmax";
    case CullMode::Full: return "full";
  }
  return "unknown";
}

CullMode parseCullMode(const std::string& name) {
  for (CullMode m : {CullMode::None, CullMode::ZMax, CullMode::Full})
    if (cullModeName(m) == name) return m;
  throw Error(fmt::format("unknown culling mode '{}' (known: none, zmax, full)", name));
}

std::vector<std::string> techniqueNames() {
  std::vector<std::string> names;
  for (const auto& n : kNames) names.push_back(n.name);
  return names;
}

}  // namespace penumbra
