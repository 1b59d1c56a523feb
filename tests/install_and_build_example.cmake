# Test, and fixture of the plug-in tests: `cmake --install` the build into a fresh prefix, check
# that the package holds only the hardware-side libraries, copy examples/out_of_tree somewhere of
# its own, build it against the prefix alone, and check its compile lines: the installed headers
# are used, and no include path names MuJoCo or Plywood's source tree. The plug-in it builds is
# WORK_DIR/build/libplywood_example.so.
#   cmake -DBINARY_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCXX_COMPILER=...
#         [-DLAUNCHER=ccache] [-DBUILD_TYPE=...] -P install_and_build_example.cmake
foreach(var BINARY_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_and_build_example.cmake: -D${var}= is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${status}): ${command}\n${output}")
  endif()
endfunction()

set(prefix "${WORK_DIR}/prefix")
set(source "${WORK_DIR}/source")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")

run("${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${prefix}")

# The package: the three hardware-side layers, nothing that needs the simulator.
foreach(layer msgs robot perception)
  if(NOT EXISTS "${prefix}/include/${layer}")
    message(FATAL_ERROR "headers of ${layer}/ not installed under ${prefix}/include")
  endif()
endforeach()
foreach(header perception/plugins/plugin.h perception/plugins/plywood_version.h
               perception/plugins/plywood_headers.h
               perception/lines/line_extractor_registry.h robot/plugins/parameter_map.h)
  if(NOT EXISTS "${prefix}/include/${header}")
    message(FATAL_ERROR "${header} not installed under ${prefix}/include")
  endif()
endforeach()
foreach(layer sim render eval apps)
  if(EXISTS "${prefix}/include/${layer}")
    message(FATAL_ERROR "simulator-side headers installed: ${prefix}/include/${layer}")
  endif()
endforeach()
file(GLOB_RECURSE package_files "${prefix}/*/cmake/Plywood/*.cmake")
if(NOT package_files)
  message(FATAL_ERROR "no CMake package under ${prefix}/*/cmake/Plywood")
endif()
foreach(file ${package_files})
  file(READ "${file}" text)
  string(REGEX REPLACE "#[^\n]*" "" text "${text}")  # comments may say what is not needed
  string(TOLOWER "${text}" text)
  if(text MATCHES "mujoco|yaml-cpp|osmesa|glfw|png|gtest")
    message(FATAL_ERROR "${file} names a simulator-side dependency (${CMAKE_MATCH_0})")
  endif()
endforeach()

# The example, built as someone else's project: its own copy of the sources, only the prefix.
file(COPY "${SOURCE_DIR}/examples/out_of_tree/" DESTINATION "${source}")
set(configure_args -G "${GENERATOR}" "-DCMAKE_PREFIX_PATH=${prefix}"
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
if(LAUNCHER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
endif()
if(BUILD_TYPE)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
endif()
run("${CMAKE_COMMAND}" -S "${source}" -B "${build}" ${configure_args})
run("${CMAKE_COMMAND}" --build "${build}" -j 2)
if(NOT EXISTS "${build}/libplywood_example.so")
  message(FATAL_ERROR "the example did not produce ${build}/libplywood_example.so")
endif()
# Nor does the plug-in itself need MuJoCo (or any simulator-side library) at run time.
find_program(READELF readelf)
if(READELF)
  execute_process(COMMAND "${READELF}" -d "${build}/libplywood_example.so"
                  OUTPUT_VARIABLE dynamic RESULT_VARIABLE status)
  string(TOLOWER "${dynamic}" dynamic)
  if(NOT status EQUAL 0 OR dynamic MATCHES "needed[^\n]*(mujoco|yaml|png|osmesa|glfw)")
    message(FATAL_ERROR "libplywood_example.so needs a simulator-side library:\n${dynamic}")
  endif()
endif()

# Its compile lines: every include path is the prefix's, the example's own or a system one.
file(READ "${build}/compile_commands.json" commands)
string(JSON count LENGTH "${commands}")
if(count EQUAL 0)
  message(FATAL_ERROR "no compile commands in ${build}/compile_commands.json")
endif()
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON command GET "${commands}" ${i} command)
  string(REGEX MATCHALL "(-I|-isystem |-iquote |-idirafter )[^ ]+" includes "${command}")
  set(uses_prefix FALSE)
  foreach(flag ${includes})
    string(REGEX REPLACE "^(-I|-isystem |-iquote |-idirafter )" "" path "${flag}")
    string(TOLOWER "${path}" lower)
    if(lower MATCHES "mujoco")
      message(FATAL_ERROR "MuJoCo on the example's include path: ${command}")
    endif()
    if(path STREQUAL "${prefix}/include")
      set(uses_prefix TRUE)
    endif()
    string(FIND "${path}/" "${SOURCE_DIR}/" in_source)
    string(FIND "${path}/" "${WORK_DIR}/" in_work)
    if(in_source EQUAL 0 AND NOT in_work EQUAL 0)
      message(FATAL_ERROR "Plywood's source tree on the example's include path: ${command}")
    endif()
  endforeach()
  if(NOT uses_prefix)
    message(FATAL_ERROR "${prefix}/include is not on the compile line: ${command}")
  endif()
endforeach()
message(STATUS "built ${build}/libplywood_example.so against ${prefix} (${count} compile lines checked)")
