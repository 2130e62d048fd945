#pragma once
// docs/fidelity.md from what runFidelity (evaluation/fidelity.h) measured: the command and the
// machine at the top, a summary per technique, per scene a table and the image strips, the
// failure modes explained with pictures, and the scenes skipped.
#include <string>

#include "evaluation/fidelity.h"

namespace penumbra {

// `command`: the command line that produced the result, quoted at the top of the page.
std::string fidelityMarkdown(const FidelityResult& result, const std::string& command);

// One CSV line per (scene, technique) row, with a header: every number of the page.
std::string fidelityCsv(const FidelityResult& result);

}  // namespace penumbra
