#pragma once
// The fidelity page's "Failure modes" section: each visible failure of the approximate
// techniques explained (with the paper section that names it) and shown by the strip of the
// scene that shows it best, with the numbers this run measured there. A mode whose scene or
// technique was not run says so instead of a picture.
#include <string>

#include "evaluation/fidelity.h"

namespace penumbra {

std::string fidelityFailureModes(const FidelityResult& result);

}  // namespace penumbra
