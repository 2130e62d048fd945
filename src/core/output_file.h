#pragma once
// Every output file (PNG, EXR, stats JSON) is written whole or not at all: the bytes go to a
// temporary file in the target's folder, every write and the close are checked, and only then
// is it renamed over the target. A full disk or an unwritable folder is an error naming the
// file and the reason, never a 0-byte or truncated file and exit code 0.
#include <string>
#include <string_view>

namespace penumbra {

// `what` names the kind of output in messages ("PNG", "stats file"). A target that exists and
// is not a regular file (a device such as /dev/stdout or /dev/full, a pipe) is written in
// place, checked the same way: renaming over it would replace the device.
void writeFileAtomically(const std::string& path, std::string_view bytes, std::string_view what);

}  // namespace penumbra
