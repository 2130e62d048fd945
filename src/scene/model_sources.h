#pragma once
// Which "models:" files a scene file needs, and which of them scripts/fetch-models.sh can fetch
// (its table, scripts/models.tsv): what `penumbra scenes` reports as ready, fetchable or
// optional.
#include <string>
#include <vector>

namespace penumbra {

// The "models:NAME" files the scene file's meshes name (NAME only), in order. Throws
// penumbra::Error naming the file when it cannot be read or is not JSON.
std::vector<std::string> sceneFileModels(const std::string& scene_path);

// The model files the fetch table lists (its first column; '#' lines are comments). Empty when
// the table cannot be read.
std::vector<std::string> fetchableModels(const std::string& table_path);

}  // namespace penumbra
