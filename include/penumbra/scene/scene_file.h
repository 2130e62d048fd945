#pragma once
// The JSON scene format, documented in docs/scene-format.md.
#include <string>

#include <penumbra/scene/scene.h>

namespace penumbra {

// Reads a scene file. Relative mesh paths are relative to the scene file's folder; a path
// starting with "models:" is looked up in $PENUMBRA_MODELS (default ../shared/models beside the
// source tree). Throws penumbra::Error naming the file and the offending key.
Scene loadSceneFile(const std::string& path);
// Same, from JSON text; `origin` names the text in messages, `base_dir` resolves relative paths.
Scene parseSceneJson(const std::string& text, const std::string& origin,
                     const std::string& base_dir);

// Folder holding the shared test models: $PENUMBRA_MODELS, else PENUMBRA_DEFAULT_MODELS_DIR.
std::string modelsDirectory();

}  // namespace penumbra
