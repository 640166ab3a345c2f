# Installation of the library users link (included by the top-level CMakeLists.txt once every
# impl/ subsystem is defined): the public headers of impl/include/swarmcheck and the spec headers
# they use, the static libraries, and a CMake package so that find_package(swarmcheck) works.
#
# Imported targets: swarmcheck::swarmcheck (exploration, and through it the two below, so that
# one target gives all three headers), swarmcheck::supervisor, swarmcheck::mission.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

target_link_libraries(swarmcheck_impl INTERFACE swarmcheck_impl_supervisor swarmcheck_impl_mission)
foreach(spec swarmcheck_spec_supervisor swarmcheck_spec_mission)
  target_include_directories(${spec} PUBLIC $<INSTALL_INTERFACE:include/swarmcheck>)
endforeach()

install(DIRECTORY ${CMAKE_SOURCE_DIR}/impl/include/swarmcheck DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/spec DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/swarmcheck
  FILES_MATCHING PATTERN "*.hpp")
install(TARGETS swarmcheck_impl swarmcheck_impl_supervisor swarmcheck_impl_mission swarmcheck_impl_io
    swarmcheck_spec_exploration swarmcheck_spec_supervisor swarmcheck_spec_mission swarmcheck_spec_util
  EXPORT swarmcheckTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} ${CMAKE_INSTALL_INCLUDEDIR}/swarmcheck)
install(EXPORT swarmcheckTargets NAMESPACE swarmcheck:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/swarmcheck)
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/swarmcheckConfig.cmake.in
  ${CMAKE_BINARY_DIR}/swarmcheckConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/swarmcheck)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/swarmcheckConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/swarmcheckConfig.cmake ${CMAKE_BINARY_DIR}/swarmcheckConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/swarmcheck)
