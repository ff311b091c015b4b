# The API reference: Doxygen over the public headers (include/dlpverify) only, built by the `docs`
# target into <build>/docs/html. Every public type, function and member needs a comment: an
# undocumented one is a warning, and any warning fails the target (FAIL_ON_WARNINGS lists them all
# first), so CI (scripts/test.sh) fails on it. Not part of `all`: a build need not have Doxygen.
find_package(Doxygen)
if(DOXYGEN_FOUND)
  set(DOXYGEN_PROJECT_NAME dlpverify)
  set(DOXYGEN_PROJECT_NUMBER ${PROJECT_VERSION})
  set(DOXYGEN_PROJECT_BRIEF "Convergence studies of ODE integrators: observed orders against closed forms and CVODE")
  set(DOXYGEN_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/docs)
  set(DOXYGEN_STRIP_FROM_PATH ${CMAKE_SOURCE_DIR}/include)
  set(DOXYGEN_STRIP_FROM_INC_PATH ${CMAKE_SOURCE_DIR}/include)
  set(DOXYGEN_FILE_PATTERNS *.hpp)
  set(DOXYGEN_JAVADOC_AUTOBRIEF YES)  # a comment's first sentence is its brief, in the member lists
  set(DOXYGEN_EXTRACT_ALL NO)
  set(DOXYGEN_EXTRACT_PRIVATE NO)
  set(DOXYGEN_EXTRACT_STATIC YES)
  set(DOXYGEN_WARN_IF_UNDOCUMENTED YES)
  set(DOXYGEN_WARN_IF_DOC_ERROR YES)
  set(DOXYGEN_WARN_IF_INCOMPLETE_DOC YES)
  set(DOXYGEN_WARN_AS_ERROR FAIL_ON_WARNINGS)
  set(DOXYGEN_WARN_FORMAT "$file:$line: $text")
  set(DOXYGEN_QUIET YES)
  set(DOXYGEN_GENERATE_HTML YES)
  set(DOXYGEN_GENERATE_LATEX NO)
  set(DOXYGEN_GENERATE_TREEVIEW YES)
  set(DOXYGEN_HAVE_DOT NO)
  set(DOXYGEN_SORT_MEMBER_DOCS NO)
  set(DOXYGEN_SHOW_INCLUDE_FILES YES)
  set(DOXYGEN_FULL_PATH_NAMES YES)
  # The one macro of the headers is a pragma; its expansion is not API.
  set(DOXYGEN_MACRO_EXPANSION NO)
  doxygen_add_docs(docs ${CMAKE_SOURCE_DIR}/include/dlpverify
                   WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                   COMMENT "API reference (Doxygen) into ${CMAKE_BINARY_DIR}/docs/html")
else()
  add_custom_target(docs
    COMMAND ${CMAKE_COMMAND} -E echo "docs: Doxygen not found (scripts/install-deps.sh installs it)"
    COMMAND ${CMAKE_COMMAND} -E false)
endif()
