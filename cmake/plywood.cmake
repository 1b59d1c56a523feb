# Helpers shared by every folder. Sources are found by name, Cartographer-style:
#   foo.cc          -> part of the folder's library
#   foo_test.cc     -> its own GoogleTest executable, registered with CTest
#   foo_main.cc     -> not built here (apps/ owns executables)

# Hardware-side folders (msgs/, robot/, perception/) run on real robots: they may include only the
# standard library, Eigen and each other. The check runs at build time, before the library compiles,
# so a forbidden include fails the build rather than being found in review.
set(PLYWOOD_INCLUDE_POLICY_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/check_hardware_includes.cmake")

function(plywood_enforce_hardware_only target folder)
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/${target}_include_policy.stamp")
  file(GLOB_RECURSE checked CONFIGURE_DEPENDS "${folder}/*.h" "${folder}/*.cc")
  add_custom_command(
    OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} -DFOLDER=${folder} -DSTAMP=${stamp} -P "${PLYWOOD_INCLUDE_POLICY_SCRIPT}"
    DEPENDS ${checked} "${PLYWOOD_INCLUDE_POLICY_SCRIPT}"
    COMMENT "Checking ${folder} includes only std and Eigen")
  add_custom_target(${target}_include_policy DEPENDS "${stamp}")
  add_dependencies(${target} ${target}_include_policy)
endfunction()

# Adds a library named `target` from every non-test .cc in the current folder.
function(plywood_add_folder_library target)
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cc")
  list(FILTER sources EXCLUDE REGEX "_(test|main)\\.cc$")
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC "${CMAKE_SOURCE_DIR}")
endfunction()

# Registers every *_test.cc in the current folder as its own test executable linked to `libs`.
function(plywood_add_folder_tests prefix)
  if(NOT PLYWOOD_BUILD_TESTS)
    return()
  endif()
  file(GLOB tests CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*_test.cc")
  foreach(test_source ${tests})
    get_filename_component(name "${test_source}" NAME_WE)
    set(test_target "${prefix}.${name}")
    add_executable(${test_target} "${test_source}")
    target_link_libraries(${test_target} PRIVATE ${ARGN} plywood_test_support GTest::gtest GTest::gtest_main)
    target_compile_definitions(${test_target} PRIVATE
      PLYWOOD_SOURCE_ROOT="${CMAKE_SOURCE_DIR}"
      PLYWOOD_BINARY_DIR="${CMAKE_BINARY_DIR}")
    add_test(NAME ${test_target} COMMAND ${test_target} WORKING_DIRECTORY "${CMAKE_BINARY_DIR}")
  endforeach()
endfunction()
