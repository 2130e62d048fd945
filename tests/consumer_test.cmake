# InstalledPackage.FindPackageConsumer: installs the build tree into a fresh prefix, builds the
# program in tests/consumer/ against it with find_package(Penumbra), and runs it. Fails when any
# step does. Run by ctest as
#   cmake -DBUILD_DIR=<build tree> -DCONSUMER_DIR=<tests/consumer> -DWORK_DIR=<scratch folder>
#         -DCXX_COMPILER=<compiler> -DGENERATOR=<generator> -P consumer_test.cmake
foreach(var BUILD_DIR CONSUMER_DIR WORK_DIR CXX_COMPILER GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "consumer_test.cmake: -D${var}=... is missing")
  endif()
endforeach()

# Only this test writes here, so it runs beside the other tests under ctest -j.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}): ${ARGN}")
  endif()
endfunction()

step("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
step("configure the consumer" "${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${WORK_DIR}/build"
     -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
     "-DCMAKE_PREFIX_PATH=${prefix}")
step("build the consumer" "${CMAKE_COMMAND}" --build "${WORK_DIR}/build")
step("run the consumer" "${WORK_DIR}/build/penumbra_consumer")
