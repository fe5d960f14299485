# Writes the source of `gas --version`'s facts (version_info.cpp.in): the
# project's version and the git commit it is built from. Run by CMake at
# every build (CMakeLists.txt, target gas_version_info) as
#   cmake -DSOURCE_DIR=... -DVERSION=... -DOUTPUT=... -P version_info.cmake
# Not one of the article's stages: the program's packaging.
#
# The commit is `git describe --always --dirty` of SOURCE_DIR when it is a
# checkout (it has its own .git: a tarball unpacked inside some other
# repository must not take that repository's commit), else "unknown". The
# file is rewritten only when its text changes (configure_file's rule), so a
# build with nothing new compiles nothing.
set(GAS_COMMIT unknown)
if(EXISTS ${SOURCE_DIR}/.git)
  find_package(Git QUIET)
  if(Git_FOUND)
    execute_process(
      COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=12
      WORKING_DIRECTORY ${SOURCE_DIR}
      OUTPUT_VARIABLE described
      OUTPUT_STRIP_TRAILING_WHITESPACE
      RESULT_VARIABLE status
      ERROR_QUIET)
    if(status EQUAL 0 AND described)
      set(GAS_COMMIT ${described})
    endif()
  endif()
endif()
set(GAS_VERSION ${VERSION})
configure_file(${CMAKE_CURRENT_LIST_DIR}/version_info.cpp.in ${OUTPUT} @ONLY)
