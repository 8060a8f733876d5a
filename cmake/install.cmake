# Installation: the libraries, their headers under <prefix>/include/quadmesh, and a
# package config so that another project does
#   find_package(quadmesh REQUIRED)
#   target_link_libraries(app PRIVATE quadmesh::core)   # or quadmesh::io
# and includes <quadmesh/quadmesh.h> (examples/embed).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(QUADMESH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/quadmesh)
set(quadmesh_install_targets quadmesh_core)
if(QUADMESH_BUILD_IO)
  list(APPEND quadmesh_install_targets quadmesh_io)
endif()
if(QUADMESH_BUILD_TOOLS)
  install(TARGETS quadmesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(TARGETS ${quadmesh_install_targets} EXPORT quadmeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/include/quadmesh/quadmesh.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadmesh)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/libquadmesh/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadmesh/libquadmesh FILES_MATCHING PATTERN "*.h")
if(QUADMESH_BUILD_IO)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/io/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/quadmesh/io FILES_MATCHING PATTERN "*.h")
endif()

install(EXPORT quadmeshTargets NAMESPACE quadmesh:: DESTINATION ${QUADMESH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/quadmeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/quadmeshConfig.cmake
                              INSTALL_DESTINATION ${QUADMESH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/quadmeshConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
# the static libraries link CHOLMOD (and Gmsh for io): users' builds find them
# with the same find modules
install(FILES ${PROJECT_BINARY_DIR}/quadmeshConfig.cmake ${PROJECT_BINARY_DIR}/quadmeshConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake ${PROJECT_SOURCE_DIR}/cmake/FindGmsh.cmake
        DESTINATION ${QUADMESH_CMAKE_DIR})
