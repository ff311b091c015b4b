# Install rules and the CMake package: find_package(dlpverify CONFIG) gives the namespaced targets
# dlpverify::harness, dlpverify::sundials, dlpverify::references, dlpverify::dlp and dlpverify::study, the dlpverify
# command, and dlpverify_add_check / dlpverify_add_suite (cmake/dlpverifyChecks.cmake).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

foreach(target dlpverify_harness dlpverify_sundials dlpverify_references dlpverify_dlp dlpverify_study)
  string(REPLACE "dlpverify_" "" short ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${short} POSITION_INDEPENDENT_CODE ON)
  add_library(dlpverify::${short} ALIAS ${target})
endforeach()

# dlpverify_simd (SLEEF's vector pow and cbrt) comes along as what dlpverify::dlp links.
set_target_properties(dlpverify_simd PROPERTIES EXPORT_NAME simd POSITION_INDEPENDENT_CODE ON)
install(TARGETS dlpverify_harness dlpverify_sundials dlpverify_references dlpverify_dlp dlpverify_study dlpverify_simd EXPORT dlpverifyTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS dlpverify RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY include/dlpverify DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT dlpverifyTargets NAMESPACE dlpverify:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/dlpverify)

set(DLPVERIFY_COMMAND ${CMAKE_INSTALL_BINDIR}/dlpverify)  # DLPVERIFY_EXECUTABLE, for dlpverify_add_check
configure_package_config_file(cmake/dlpverifyConfig.cmake.in ${CMAKE_BINARY_DIR}/dlpverifyConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/dlpverify PATH_VARS DLPVERIFY_COMMAND)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/dlpverifyConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/dlpverifyConfig.cmake ${CMAKE_BINARY_DIR}/dlpverifyConfigVersion.cmake
              cmake/dlpverifyChecks.cmake cmake/FindQD.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/dlpverify)
