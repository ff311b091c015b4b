# Finds QD's double-double (Debian's libqd-dev) and defines the imported target QD::qd. QD ships
# no CMake package, and Debian's qd.pc names an include folder that does not exist
# (/usr/lib/x86_64-linux-gnu/fortran/$fortran), which CMake's pkg-config targets refuse; so its
# header and library are found directly. Installed with the dlpverify package, whose config uses it.
find_path(QD_INCLUDE_DIR qd/dd_real.h)
find_library(QD_LIBRARY qd)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(QD REQUIRED_VARS QD_LIBRARY QD_INCLUDE_DIR)
if(QD_FOUND AND NOT TARGET QD::qd)
  add_library(QD::qd UNKNOWN IMPORTED)
  set_target_properties(QD::qd PROPERTIES IMPORTED_LOCATION "${QD_LIBRARY}"
                                          INTERFACE_INCLUDE_DIRECTORIES "${QD_INCLUDE_DIR}")
endif()
mark_as_advanced(QD_INCLUDE_DIR QD_LIBRARY)
