# `cmake --install build --prefix P`: the hardware-side libraries plywood::msgs, plywood::robot
# and plywood::perception (static, position-independent, std + Eigen + zlib only), their headers
# under P/include with their msgs/, robot/, perception/ paths, and the CMake package
# P/lib/cmake/Plywood, so a robot's own code or a plug-in (docs/plugins.md) does
# find_package(Plywood) on a machine without MuJoCo. Nothing simulator-side is installed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PLYWOOD_PACKAGE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/Plywood")
foreach(layer msgs robot perception)
  set_target_properties(plywood_${layer} PROPERTIES EXPORT_NAME ${layer})
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${layer}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/${layer}"
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES "${PLYWOOD_VERSION_HEADER}" "${PLYWOOD_HEADERS_HASH_HEADER}"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/perception/plugins")
install(TARGETS plywood_msgs plywood_robot plywood_perception EXPORT PlywoodTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(EXPORT PlywoodTargets NAMESPACE plywood:: DESTINATION "${PLYWOOD_PACKAGE_DIR}")

configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/PlywoodConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/PlywoodConfig.cmake"
                              INSTALL_DESTINATION "${PLYWOOD_PACKAGE_DIR}")
# A plug-in must match the host's version exactly (checked when it is loaded); the package itself
# accepts any 0.1.x request.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/PlywoodConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/PlywoodConfig.cmake"
              "${PROJECT_BINARY_DIR}/PlywoodConfigVersion.cmake"
        DESTINATION "${PLYWOOD_PACKAGE_DIR}")
