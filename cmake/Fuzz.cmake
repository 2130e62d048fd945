# libFuzzer targets for the mesh loaders (OBJ, PLY, glTF text and binary) and the scene-file reader:
# penumbra_fuzz_obj, penumbra_fuzz_ply, penumbra_fuzz_gltf, penumbra_fuzz_scene. Clang only
# (Debian: clang-14, libclang-rt-14-dev); combine with PENUMBRA_SANITIZE=ON for ASan + UBSan.
# scripts/fuzz.sh configures, builds and runs them. They compile only src/core (with the image
# reader that scene files' PNG light textures need) and src/scene, the code under test, with
# coverage instrumentation, not the whole library.
option(PENUMBRA_BUILD_FUZZ "Build the libFuzzer targets (needs clang)" OFF)

if(PENUMBRA_BUILD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PENUMBRA_BUILD_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++)")
  endif()
  file(GLOB PENUMBRA_FUZZ_LIB_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/core/*.cpp
       ${PROJECT_SOURCE_DIR}/src/scene/*.cpp)
  add_library(penumbra_fuzz_lib STATIC ${PENUMBRA_FUZZ_LIB_SOURCES})
  target_compile_options(penumbra_fuzz_lib PUBLIC -fsanitize=fuzzer-no-link)
  target_include_directories(penumbra_fuzz_lib
    PUBLIC ${PROJECT_SOURCE_DIR}/include ${PROJECT_SOURCE_DIR}/include/penumbra
           ${PROJECT_SOURCE_DIR}/src)
  # src/scene/scene_file.cpp gets its models paths from its source properties (CMakeLists.txt).
  target_compile_definitions(penumbra_fuzz_lib PUBLIC GLM_FORCE_XYZW_ONLY)
  target_link_libraries(penumbra_fuzz_lib
    PUBLIC glm::glm fmt::fmt TBB::tbb assimp::assimp meshoptimizer::meshoptimizer
           nlohmann_json::nlohmann_json hwy::hwy Threads::Threads PNG::PNG tinyexr::tinyexr)

  foreach(format obj ply gltf)
    set(extension ".${format}")
    add_executable(penumbra_fuzz_${format} ${PROJECT_SOURCE_DIR}/fuzz/fuzz_mesh_file.cpp)
    target_compile_definitions(penumbra_fuzz_${format} PRIVATE PENUMBRA_FUZZ_EXTENSION="${extension}")
    target_link_libraries(penumbra_fuzz_${format} PRIVATE penumbra_fuzz_lib)
    target_link_options(penumbra_fuzz_${format} PRIVATE -fsanitize=fuzzer)
  endforeach()
  add_executable(penumbra_fuzz_scene ${PROJECT_SOURCE_DIR}/fuzz/fuzz_scene_json.cpp)
  target_link_libraries(penumbra_fuzz_scene PRIVATE penumbra_fuzz_lib)
  target_link_options(penumbra_fuzz_scene PRIVATE -fsanitize=fuzzer)
endif()
