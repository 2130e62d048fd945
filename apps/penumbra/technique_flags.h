#pragma once
// Technique options as command-line flags: every option name any registered technique has,
// once, with the techniques that take it (shadows/technique.h).
#include <string>
#include <vector>

#include "shadows/technique.h"

namespace penumbra::cli {

struct TechniqueOptionUse {
  const OptionSpec* spec = nullptr;     // the first technique's spec of that name
  std::vector<std::string> techniques;  // every technique that has it
};

// Throws penumbra::Error when two techniques give one name different kinds (a flag and a
// value), which one command-line option could not serve.
std::vector<TechniqueOptionUse> techniqueOptionUses();

}  // namespace penumbra::cli
