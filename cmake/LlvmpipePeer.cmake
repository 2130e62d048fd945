# penumbra_llvmpipe_peer: Mesa's llvmpipe running z-fail stencil shadow volumes on our scenes,
# the peer our hard-shadow timings are quoted against (bench/peer/). Built only where EGL and
# libepoxy are installed (scripts/setup-debian.sh installs them); the rest of the project never
# needs OpenGL.
option(PENUMBRA_BUILD_LLVMPIPE_PEER "Build the llvmpipe benchmark peer when EGL and epoxy exist" ON)

if(PENUMBRA_BUILD_LLVMPIPE_PEER)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(PENUMBRA_PEER_EGL QUIET IMPORTED_TARGET egl)
    pkg_check_modules(PENUMBRA_PEER_EPOXY QUIET IMPORTED_TARGET epoxy)
  endif()
  if(PENUMBRA_PEER_EGL_FOUND AND PENUMBRA_PEER_EPOXY_FOUND)
    file(GLOB PENUMBRA_PEER_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/bench/peer/*.cpp)
    add_executable(penumbra_llvmpipe_peer ${PENUMBRA_PEER_SOURCES})
    target_include_directories(penumbra_llvmpipe_peer PRIVATE ${PROJECT_SOURCE_DIR}/src
                               ${PROJECT_SOURCE_DIR}/bench/peer)
    target_link_libraries(penumbra_llvmpipe_peer PRIVATE penumbra_core PkgConfig::PENUMBRA_PEER_EGL
                          PkgConfig::PENUMBRA_PEER_EPOXY meshoptimizer::meshoptimizer
                          CLI11::CLI11 nlohmann_json::nlohmann_json)
  else()
    message(STATUS "penumbra_llvmpipe_peer skipped: needs pkg-config modules egl and epoxy "
                   "(Debian: libegl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri)")
  endif()
endif()
