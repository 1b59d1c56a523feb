# Sanitizer builds. -DPLYWOOD_SANITIZE=ON (scripts/sanitize): every target with AddressSanitizer
# and UndefinedBehaviorSanitizer, float-cast-overflow included (GCC's `undefined` leaves it out);
# the first finding aborts the process, so a finding fails its test. -DPLYWOOD_FUZZ=ON
# (scripts/fuzz, clang only): the same sanitizers plus libFuzzer's coverage instrumentation on
# every library, so the fuzz/ harnesses find memory errors and UB, not only crashes.
set(PLYWOOD_SANITIZERS address,undefined,float-cast-overflow)
if(PLYWOOD_SANITIZE OR PLYWOOD_FUZZ)
  add_compile_options(-fsanitize=${PLYWOOD_SANITIZERS} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PLYWOOD_SANITIZERS})
  # -O1, as the sanitizers' own documentation advises: the reports keep their line numbers and the
  # instrumented build (all of it again in CI) compiles in about half the time of -O2.
  add_compile_options(-O1)
  # Tests whose Monte-Carlo draws or real-log replays only need their code paths covered here
  # draw fewer of them (their figures are the plain build's to check).
  add_compile_definitions(PLYWOOD_SANITIZED_BUILD)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC 12 with -fsanitize=address reports -Wmaybe-uninitialized inside libstdc++'s std::function
    # as std::regex uses it (a false positive of the instrumented code; the plain build keeps the
    # warning), which -Werror would turn into a failed build.
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
endif()
if(PLYWOOD_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "PLYWOOD_FUZZ needs clang's libFuzzer: configure with "
                        "CC=clang CXX=clang++ (scripts/fuzz does)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

# Every test of a sanitizer build runs with these options (ctest reads the file before the tests),
# so plain `ctest` in the build folder is the sanitizer run, child processes included. Leak
# suppressions cover third-party libraries only, each justified in cmake/lsan_suppressions.txt.
# Not fast_unwind_on_malloc=0: ASan's slow unwinder takes libgcc's frame lock inside malloc, and
# llvmpipe's JIT registers its unwind tables (__register_frame -> malloc) under that same lock, so
# every test that draws a snapshot deadlocked.
if(PLYWOOD_SANITIZE)
  set(suppressions "${CMAKE_CURRENT_LIST_DIR}/lsan_suppressions.txt")
  set(environment_file "${PROJECT_BINARY_DIR}/sanitizer_environment.cmake")
  file(WRITE "${environment_file}"
       "set(ENV{ASAN_OPTIONS} \"detect_leaks=1:strict_string_checks=1:check_initialization_order=1\")\n"
       "set(ENV{LSAN_OPTIONS} \"suppressions=${suppressions}:print_suppressions=0\")\n"
       "set(ENV{UBSAN_OPTIONS} \"print_stacktrace=1:halt_on_error=1\")\n")
  set_property(DIRECTORY "${PROJECT_SOURCE_DIR}" APPEND PROPERTY TEST_INCLUDE_FILES
                                                                 "${environment_file}")
endif()

# `sanitize_ci`: what scripts/sanitize --ci builds and runs (ctest labels msgs, robot, perception):
# the hardware layers' unit tests, i.e. the code that runs on a real robot, and the corpora of the
# perception/ parsers. It needs no simulator library, which keeps it inside the CI budget (see
# docs/sanitizers.md). Call after every folder is added.
function(plywood_add_sanitize_ci_target)
  if(NOT PLYWOOD_BUILD_TESTS OR PLYWOOD_FUZZ)
    return()
  endif()
  add_custom_target(sanitize_ci)
  foreach(layer msgs robot perception)
    get_property(targets GLOBAL PROPERTY PLYWOOD_TEST_TARGETS_${layer})
    add_dependencies(sanitize_ci ${targets})
  endforeach()
  add_dependencies(sanitize_ci fuzz_replay_perception)
endfunction()
