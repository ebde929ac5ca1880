# Installation and the CMake package (find_package(tritri)): libraries, headers, the tritri
# command, and a config that finds the same Debian packages tritri was built with.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(_tritri_algorithm_folders GLOBAL PROPERTY TRITRI_ALGORITHM_FOLDERS)
set(_tritri_algorithm_targets "")
foreach(folder IN LISTS _tritri_algorithm_folders)
  list(APPEND _tritri_algorithm_targets tritri_algo_${folder})
endforeach()

set_target_properties(tritri_api PROPERTIES EXPORT_NAME api)
set_target_properties(tritri_harness PROPERTIES EXPORT_NAME harness)
set_target_properties(tritri_corpus PROPERTIES EXPORT_NAME corpus)
set_target_properties(tritri_testing PROPERTIES EXPORT_NAME testing)
set_target_properties(tritri_oracle PROPERTIES EXPORT_NAME oracle)
set_target_properties(tritri_algorithms PROPERTIES EXPORT_NAME algorithms)

install(TARGETS tritri_api tritri_algorithms ${_tritri_algorithm_targets} tritri_oracle tritri_harness
                tritri_corpus tritri_testing
        EXPORT tritriTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS tritri RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/algorithms/api/tritri DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
install(FILES ${PROJECT_SOURCE_DIR}/harness/testing/tritri/testing.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/harness/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri/harness
        FILES_MATCHING PATTERN "*.hpp" PATTERN "cli" EXCLUDE PATTERN "bench" EXCLUDE PATTERN "testing" EXCLUDE
        PATTERN "test_support" EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/generator/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tritri/corpus
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_SOURCE_DIR}/cases/builtin.cases ${PROJECT_SOURCE_DIR}/cases/yuhe13.cases
              ${PROJECT_SOURCE_DIR}/cases/sabharwal15.cases
        DESTINATION ${CMAKE_INSTALL_DATADIR}/tritri/cases)

install(EXPORT tritriTargets NAMESPACE tritri:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tritriConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/tritriConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/tritriConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/tritriConfig.cmake ${CMAKE_BINARY_DIR}/tritriConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/tritri)
