# Helpers shared by every folder. Sources are found by name, Cartographer-style:
#   foo.cc          -> part of the top-level folder's library (subfolders included: a folder per
#                      capability, one library per layer)
#   foo_test.cc     -> its own GoogleTest executable <layer>.foo_test, registered with CTest
#   foo_main.cc     -> not built here (apps/ owns executables)

# Each layer may include only the layers below it. Hardware-side folders (msgs/, robot/,
# perception/) run on real robots: standard library, Eigen and each other only. The check runs at
# build time, before the library compiles, so a forbidden include fails the build rather than being
# found in review.
set(PLYWOOD_INCLUDE_POLICY_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/check_hardware_includes.cmake")
set(PLYWOOD_HARDWARE_FORBIDDEN "mujoco/|mujoco\\.h|GL/|GLFW/|yaml-cpp/|nlohmann/|CLI/|imgui|sim/|render/|eval/|viewer/|apps/")

# Fails the build of `target` when a file under `folder` includes anything matching `forbidden`
# (a regex on the include path; default: what hardware-side code may never include).
function(plywood_enforce_includes target folder)
  set(forbidden "${ARGN}")
  if(NOT forbidden)
    set(forbidden "${PLYWOOD_HARDWARE_FORBIDDEN}")
  endif()
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/${target}_include_policy.stamp")
  file(GLOB_RECURSE checked CONFIGURE_DEPENDS "${folder}/*.h" "${folder}/*.cc")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} "-DFOLDER=${folder}" "-DSTAMP=${stamp}" "-DFORBIDDEN=${forbidden}"
            -P "${PLYWOOD_INCLUDE_POLICY_SCRIPT}"
    DEPENDS ${checked} "${PLYWOOD_INCLUDE_POLICY_SCRIPT}"
    COMMENT "Checking the includes of ${folder}"
    VERBATIM)
  add_custom_target(${target}_include_policy DEPENDS "${stamp}")
  add_dependencies(${target} ${target}_include_policy)
endfunction()

function(plywood_enforce_hardware_only target folder)
  plywood_enforce_includes(${target} "${folder}")
endfunction()

# A cold build (CI builds everything from scratch, the hardware layers twice) compiled each library
# source on its own: the inline and template code of the headers they share (Eigen, the standard
# library, the layer's own) was instantiated and optimised again in every object. Unity batches
# compile several sources in one translation unit, which roughly halves a library's compile time.
# The price: names local to a source (anonymous namespace) must be unique within its library, since
# sources share a batch; a clash fails the build, it cannot change a result. Turn it off for
# quicker rebuilds of a single file while working on one library.
option(PLYWOOD_UNITY_BUILD "Compile each library's sources in unity batches" ON)
set(PLYWOOD_UNITY_BUILD_BATCH_SIZE 8 CACHE STRING "Sources per unity batch")

# Adds a library named `target` from every non-test .cc in the current folder and its subfolders.
function(plywood_add_folder_library target)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cc")
  list(FILTER sources EXCLUDE REGEX "_(test|main|fuzz)\\.cc$")
  add_library(${target} STATIC ${sources})
  # Position-independent so a user's plug-in (a shared library) can link the installed archives.
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  if(PLYWOOD_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE
                                               ${PLYWOOD_UNITY_BUILD_BATCH_SIZE})
  endif()
  target_include_directories(${target} PUBLIC "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>"
                                              "$<INSTALL_INTERFACE:include>")
  # The headers need C++20 in a user's project too (the installed package carries it).
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()

# A cold build (CI builds everything from scratch, the hardware layers twice) spends most of each
# library source's time parsing the standard library's and Eigen's headers again: each large library
# parses them once, into a precompiled header its sources share. The headers are force-included, so
# a source missing an include still compiles here: scripts/sanitize (in CI for msgs/, robot/ and
# perception/, the installed layers) builds with -DPLYWOOD_LIBRARY_PCH=OFF and so still fails on it.
option(PLYWOOD_LIBRARY_PCH "Precompile each large library's common headers" ON)
set(PLYWOOD_LIBRARY_PCH_HEADERS
    <Eigen/Core> <Eigen/Geometry> <algorithm> <array> <cmath> <cstddef> <cstdint> <functional>
    <limits> <map> <memory> <numbers> <optional> <span> <stdexcept> <string> <string_view>
    <utility> <vector>)

# Gives `target` the common precompiled header plus `ARGN` (headers only that layer may include).
function(plywood_precompile_library_headers target)
  if(PLYWOOD_LIBRARY_PCH)
    target_precompile_headers(${target} PRIVATE ${PLYWOOD_LIBRARY_PCH_HEADERS} ${ARGN})
  endif()
endfunction()

# What every test's precompiled header holds: GoogleTest, Eigen and the standard headers the tests
# use most; simulator-side tests add MuJoCo and yaml-cpp (hardware-side ones may not include them).
set(PLYWOOD_TEST_PCH_HEADERS
    <gtest/gtest.h> <Eigen/Core> <Eigen/Geometry> <algorithm> <cmath> <cstdint> <filesystem>
    <fstream> <functional> <limits> <map> <memory> <numbers> <random> <sstream> <stdexcept>
    <string> <utility> <vector>)
set(PLYWOOD_SIM_TEST_PCH_HEADERS <mujoco/mujoco.h> <yaml-cpp/yaml.h>)

# Tests compile at -O1 in the optimised builds: a test's own code is set-up and assertions (the
# code under test is the libraries', at the build's -O2), and optimising GoogleTest's expanded
# macros harder was ~20 % of the test sources' compile time in a cold build. The precompiled
# header's holder gets the same flag, which GCC needs to reuse it.
set(PLYWOOD_TEST_OPTIMIZATION $<$<CONFIG:RelWithDebInfo,Release,MinSizeRel>:-O1>)
# The tests of a side share one precompiled header (below): a test whose flags made GCC reject it
# would silently parse every header again, so GCC's warning for that, an error under -Werror, says so.
set(PLYWOOD_TEST_COMPILE_OPTIONS ${PLYWOOD_TEST_OPTIMIZATION} $<$<CXX_COMPILER_ID:GNU>:-Winvalid-pch>)

# Registers every *_test.cc in the current folder and its subfolders as its own test executable
# <prefix>.<name> linked to `libs` (simulator-side folders add plywood_test_support, which needs
# the simulator; hardware-side tests build with their own layers alone).
function(plywood_add_folder_tests prefix)
  if(NOT PLYWOOD_BUILD_TESTS)
    return()
  endif()
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*_test.cc")
  if(NOT tests)
    return()
  endif()
  # GoogleTest, Eigen and the standard headers are most of a test's compile time (CI builds every
  # test from scratch, twice with the sanitizers): they are parsed once into a precompiled header
  # that the tests share: one for the hardware-side layers (only what they may include), one for
  # the simulator side (MuJoCo and yaml-cpp too). The first folder of a side makes its holder; the
  # holder links what that folder's tests link, so it is compiled with their flags (one per layer
  # cost 8 precompilations of the same headers in a cold build instead of 2).
  if(prefix MATCHES "^(msgs|robot|perception)$")
    set(side hardware)
  else()
    set(side simulator)
  endif()
  get_property(pch_target GLOBAL PROPERTY PLYWOOD_TEST_PCH_${side})
  if(NOT pch_target)
    set(pch_target "plywood_${side}_test_pch")
    set(pch_source "${CMAKE_CURRENT_BINARY_DIR}/${pch_target}.cc")
    file(CONFIGURE OUTPUT "${pch_source}"
         CONTENT "// The holder of the ${side}-side tests' precompiled header.\n")
    add_library(${pch_target} OBJECT "${pch_source}")
    target_link_libraries(${pch_target} PRIVATE ${ARGN} GTest::gtest)
    target_compile_options(${pch_target} PRIVATE ${PLYWOOD_TEST_COMPILE_OPTIONS})
    set(pch_headers ${PLYWOOD_TEST_PCH_HEADERS})
    if(side STREQUAL "simulator")
      list(APPEND pch_headers ${PLYWOOD_SIM_TEST_PCH_HEADERS})
    endif()
    target_precompile_headers(${pch_target} PRIVATE ${pch_headers})
    set_property(GLOBAL PROPERTY PLYWOOD_TEST_PCH_${side} ${pch_target})
  endif()
  foreach(test_source ${tests})
    get_filename_component(name "${test_source}" NAME_WE)
    set(test_target "${prefix}.${name}")
    add_executable(${test_target} "${test_source}")
    target_link_libraries(${test_target} PRIVATE ${ARGN} GTest::gtest GTest::gtest_main)
    target_compile_options(${test_target} PRIVATE ${PLYWOOD_TEST_COMPILE_OPTIONS})
    target_precompile_headers(${test_target} REUSE_FROM ${pch_target})
    add_test(NAME ${test_target} COMMAND ${test_target} WORKING_DIRECTORY "${PROJECT_BINARY_DIR}")
    # Labelled by layer, so a subset runs by label (ctest -L perception; scripts/sanitize --ci).
    set_tests_properties(${test_target} PROPERTIES LABELS ${prefix})
    set_property(GLOBAL APPEND PROPERTY PLYWOOD_TEST_TARGETS_${prefix} ${test_target})
  endforeach()
endfunction()
