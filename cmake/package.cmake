# The Debian package: `cpack -G DEB` (in the build tree) packs what `cmake --install` installs —
# the command, the static libraries, the headers, the CMake package and the man page — under /usr.
# Its Depends field is what dpkg-shlibdeps finds the command links (SUNDIALS, GSL, HDF5, Boost, …)
# plus the -dev packages a user of the headers and the CMake package needs (find_dependency in
# cmake/dlpverifyConfig.cmake.in, and SLEEF, which dlpverify::dlp links).
# A package for other machines is built with -DDLPVERIFY_NATIVE=OFF (portable x86-64).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME dlpverify)
set(CPACK_PACKAGE_VENDOR dlpverify)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "convergence verification of ODE integrators")
set(CPACK_PACKAGE_DESCRIPTION
    "dlpverify measures the observed order of accuracy of time integrators by convergence studies against closed forms and CVODE references, and checks it in CI. The package holds the dlpverify command, the library (static), its headers and CMake package, and the man page.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES OFF)  # the static libraries must keep their symbols

set(DLPVERIFY_PACKAGE_MAINTAINER "dlpverify developers" CACHE STRING "Maintainer field of the Debian package")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${DLPVERIFY_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # dlpverify_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "libsundials-dev (>= 6.4), libeigen3-dev (>= 3.4), libgsl-dev, nlohmann-json3-dev (>= 3.10), libsleef-dev, libqd-dev")
include(CPack)
