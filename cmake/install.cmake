# The installed package: headers, the layer libraries and the CLI, and a CMake package config, so that another
# project can `find_package(dpdrng)` and link dpdrng::rng (header-only: generators, seedings, distributions)
# or any layer above it. examples/pair_force is such a consumer.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(DPDRNG_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dpdrng)
install(TARGETS dpdrng_plugin dpdrng_rng dpdrng_common dpdrng_rng_registry dpdrng_stats dpdrng_dpd dpdrng_study
  EXPORT dpdrngTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS dpdrng RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The CLI's headers stay private to the executable.
install(DIRECTORY include/dpdrng/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dpdrng
  FILES_MATCHING PATTERN "*.hpp" PATTERN "cli" EXCLUDE)
install(FILES ${DPDRNG_GENERATED_INCLUDE}/dpdrng/version.hpp include/dpdrng/plugin.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dpdrng)
install(FILES ${DPDRNG_FAMILY_INCLUDE}/dpdrng/rng/families.hpp ${DPDRNG_FAMILY_INCLUDE}/dpdrng/rng/family_headers.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dpdrng/rng)
install(EXPORT dpdrngTargets NAMESPACE dpdrng:: DESTINATION ${DPDRNG_CMAKE_DIR})

configure_package_config_file(cmake/dpdrngConfig.cmake.in ${PROJECT_BINARY_DIR}/dpdrngConfig.cmake
  INSTALL_DESTINATION ${DPDRNG_CMAKE_DIR})
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dpdrngConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dpdrngConfig.cmake ${PROJECT_BINARY_DIR}/dpdrngConfigVersion.cmake
  DESTINATION ${DPDRNG_CMAKE_DIR})
