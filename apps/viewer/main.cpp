// penumbra-view: the interactive viewer (`penumbra view SCENE` runs it). Every error ends as
// "penumbra view: error: <message>" on stderr and exit code 1.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#if defined(__GLIBC__) || __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include "viewer_app.h"
#include "viewer_args.h"

namespace {

// As the CLI does for `render --frames`: frame-sized buffers stay in the heap between frames
// instead of being unmapped and faulted in again, so the viewer loop and the CLI pay the same.
void keepFrameBuffersInHeap() {
#if defined(M_MMAP_THRESHOLD)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 64 << 20);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  keepFrameBuffersInHeap();
  try {
    const penumbra::viewer::ViewerArgs args =
        penumbra::viewer::parseViewerArgs(std::vector<std::string>(argv + 1, argv + argc));
    if (args.help) {
      std::cout << penumbra::viewer::viewerUsage();
      return 0;
    }
    penumbra::viewer::ViewerApp app(args);
    return app.run();
  } catch (const std::exception& e) {
    std::cerr << "penumbra view: error: " << e.what() << std::endl;
    return 1;
  }
}
