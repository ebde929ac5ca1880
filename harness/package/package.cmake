# Installation and the CMake package (find_package(tritri)): libraries, headers, the tritri
# command, and a config that finds the same Debian packages tritri was built with. Headers keep
# their paths under include/tritri/ ("cases/casefile.hpp"), the plug-in API under include/tritri/.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(_tritri_algorithm_folders GLOBAL PROPERTY TRITRI_ALGORITHM_FOLDERS)
set(_tritri_algorithm_targets "")
foreach(folder IN LISTS _tritri_algorithm_folders)
  list(APPEND _tritri_algorithm_targets tritri_algo_${folder})
endforeach()

foreach(layer api algorithms oracle cases corpus run check testing)
  set_target_properties(tritri_${layer} PROPERTIES EXPORT_NAME ${layer})
endforeach()

install(TARGETS tritri_api tritri_algorithms ${_tritri_algorithm_targets} tritri_oracle tritri_cases
                tritri_corpus tritri_run tritri_check tritri_testing
        EXPORT tritriTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS tritri RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The v3fma build variant's module (algorithms/CMakeLists.txt), where tritri looks for it: the
# same path relative to bin/ as in the build tree.
if(TARGET tritri_v3fma)
  install(TARGETS tritri_v3fma LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/tritri)
endif()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/algorithms/api/tritri DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/harness/testing/tritri/testing.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri
        FILES_MATCHING PATTERN "*.hpp")
foreach(concern run check)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/harness/${concern} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri/harness
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/cases/builtin.cases ${PROJECT_SOURCE_DIR}/cases/yuhe13.cases
              ${PROJECT_SOURCE_DIR}/cases/sabharwal15.cases
        DESTINATION ${CMAKE_INSTALL_DATADIR}/tritri/cases)

# Each library peer built links a library found in its folder; the package finds it again.
set(TRITRI_PEER_DEPENDENCIES "")
if(TARGET tritri_algo_open3d)
  string(APPEND TRITRI_PEER_DEPENDENCIES "find_dependency(Open3D)\n")
endif()
if(TARGET tritri_algo_bullet OR TARGET tritri_algo_ode)
  string(APPEND TRITRI_PEER_DEPENDENCIES "find_dependency(PkgConfig)\n")
endif()
if(TARGET tritri_algo_bullet)
  string(APPEND TRITRI_PEER_DEPENDENCIES "pkg_check_modules(TRITRI_BULLET REQUIRED QUIET IMPORTED_TARGET GLOBAL bullet>=3.24)\n")
endif()
if(TARGET tritri_algo_ode)
  string(APPEND TRITRI_PEER_DEPENDENCIES "pkg_check_modules(TRITRI_ODE REQUIRED QUIET IMPORTED_TARGET GLOBAL ode>=0.16)\n")
endif()
if(TARGET tritri_algo_vtk)
  string(APPEND TRITRI_PEER_DEPENDENCIES "find_dependency(VTK COMPONENTS FiltersGeneral)\n")
endif()

install(EXPORT tritriTargets NAMESPACE tritri:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/tritriConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/tritriConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/tritriConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/tritriConfig.cmake ${CMAKE_BINARY_DIR}/tritriConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
