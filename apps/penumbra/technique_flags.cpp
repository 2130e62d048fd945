#include "technique_flags.h"

#include <fmt/format.h>

#include "core/error.h"

namespace penumbra::cli {

std::vector<TechniqueOptionUse> techniqueOptionUses() {
  std::vector<TechniqueOptionUse> uses;
  for (const TechniqueInfo& info : techniques()) {
    for (const OptionSpec& spec : info.options.specs()) {
      TechniqueOptionUse* use = nullptr;
      for (TechniqueOptionUse& u : uses)
        if (u.spec->name == spec.name) use = &u;
      if (use == nullptr) {
        uses.push_back({&spec, {}});
        use = &uses.back();
      }
      PENUMBRA_CHECK(use->spec->kind == spec.kind,
                     "technique '{}' declares --{} as another kind of option than '{}' does",
                     info.name, spec.name, use->techniques.front());
      use->techniques.push_back(info.name);
    }
  }
  return uses;
}

}  // namespace penumbra::cli
