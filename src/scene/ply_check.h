#pragma once
// A strict check of a PLY file's header and body sizes, run before assimp reads the bytes.
// assimp 5.2's PLY reader has no bounds checks of its own: a header without end_header or cut
// off spins forever, a mutated binary header or a body shorter than the header declares reads
// past the buffer (segfault, bus error), and a face with zero or out-of-range indices aborts in
// triangulation. Debian packages no other PLY reader, so this walks the declared elements
// (without building anything) and refuses every file whose bytes do not match its header.
#include <string>
#include <string_view>

namespace penumbra {

// Throws penumbra::Error "<path>: <what is wrong>" when `bytes` (the whole file) is not a
// well-formed PLY: unknown header lines, no end_header, a body cut off or longer than the
// header declares, list counts that are negative, a face with fewer than 3 indices, or an
// index outside the vertex element.
void checkPlyBytes(const std::string& path, std::string_view bytes);

}  // namespace penumbra
