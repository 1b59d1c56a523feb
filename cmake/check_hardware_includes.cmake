# Fails when a file under FOLDER includes a header whose path matches FORBIDDEN (a regex; by
# default what hardware-side code may never include: MuJoCo, GL, GLFW, OSMesa, YAML, JSON, CLI
# headers and the simulator-side folders sim/, render/, eval/, viewer/, apps/).
if(NOT FORBIDDEN)
  set(FORBIDDEN "mujoco/|mujoco\\.h|GL/|GLFW/|yaml-cpp/|nlohmann/|CLI/|imgui|sim/|render/|eval/|viewer/|apps/")
endif()
file(GLOB_RECURSE files "${FOLDER}/*.h" "${FOLDER}/*.cc")
set(violations "")
foreach(f ${files})
  file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](${FORBIDDEN})")
  foreach(line ${lines})
    list(APPEND violations "${f}: ${line}")
  endforeach()
endforeach()
if(violations)
  string(REPLACE ";" "\n  " pretty "${violations}")
  message(FATAL_ERROR "${FOLDER} must not include these headers (layering, see README 'Layout'):\n  ${pretty}")
endif()
file(TOUCH "${STAMP}")
