# Installing `gas` like any Unix program (issue 25), included by
# CMakeLists.txt:
#   cmake --install build [--prefix P]   bin/gas, the teaching scenes in
#       share/gas-on-the-display/ (with data/README.md, the scene format),
#       the manual page share/man/man1/gas.1.gz, README.md, the copyright
#       and changelog.gz in share/doc/gas-on-the-display/
#   cpack --config build/CPackConfig.cmake   a Debian package of the same
#       files under /usr, its dependencies (libfmt9, ...) found by
#       dpkg-shlibdeps (Debian's dpkg-dev)
# Not one of the article's stages; the reference: README.md ("Installing").

install(TARGETS gas RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The teaching scenes: every data/*.scene, and the scenes of data/edge and
# data/hard that a lesson names (the others are the tests' own), read from
# the lessons when CMake configures. The program finds them by name
# (stages/program/scene_lookup.hpp): `gas crowd`, `gas hard/corner`.
file(GLOB GAS_TEACHING_SCENES ${CMAKE_SOURCE_DIR}/data/*.scene)
install(FILES ${GAS_TEACHING_SCENES} DESTINATION ${GAS_SCENES_FOLDER})
install(FILES data/README.md DESTINATION ${GAS_SCENES_FOLDER})
file(GLOB GAS_LESSONS ${CMAKE_SOURCE_DIR}/lessons/*.md)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${GAS_LESSONS})
set(GAS_LESSON_SCENES)
foreach(lesson IN LISTS GAS_LESSONS)
  file(READ ${lesson} text)
  string(REGEX MATCHALL "data/(edge|hard)/[A-Za-z0-9_.+-]+\\.scene" named "${text}")
  list(APPEND GAS_LESSON_SCENES ${named})
endforeach()
list(REMOVE_DUPLICATES GAS_LESSON_SCENES)
foreach(scene IN LISTS GAS_LESSON_SCENES)
  string(REGEX REPLACE "^data/([a-z]+)/.*" "\\1" folder ${scene})
  install(FILES ${scene} DESTINATION ${GAS_SCENES_FOLDER}/${folder})
endforeach()

# The manual page, its version filled in, and the package's changelog,
# installed gzipped as Debian's policy asks (gzip -9n: the most compressed,
# with no name or time in the header, so that two builds give the same
# bytes). The page's source, gas.1.in, is written by hand;
# tests/test_install.cpp checks that it names every option of --help and
# every key (the test says what is missing when an option is added), and
# that the changelog's newest entry names the project's version.
find_program(GAS_GZIP gzip REQUIRED)
function(gas_gzip input output)
  execute_process(COMMAND ${GAS_GZIP} -9n -c ${input} OUTPUT_FILE ${output}
                  COMMAND_ERROR_IS_FATAL ANY)
endfunction()
configure_file(stages/program/gas.1.in ${CMAKE_BINARY_DIR}/gas.1 @ONLY)
gas_gzip(${CMAKE_BINARY_DIR}/gas.1 ${CMAKE_BINARY_DIR}/gas.1.gz)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_SOURCE_DIR}/stages/program/changelog)
gas_gzip(${CMAKE_SOURCE_DIR}/stages/program/changelog ${CMAKE_BINARY_DIR}/changelog.gz)
install(FILES ${CMAKE_BINARY_DIR}/gas.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
# Beside README.md, what a Debian package must carry: the copyright, in
# Debian's machine-readable form (the project states no licence, and it says
# so), and the changelog.
set(GAS_DOC_FOLDER ${CMAKE_INSTALL_DATAROOTDIR}/doc/gas-on-the-display)
install(FILES README.md stages/program/copyright ${CMAKE_BINARY_DIR}/changelog.gz
        DESTINATION ${GAS_DOC_FOLDER})

# The Debian package, written into the build folder whatever the folder
# cpack runs in.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gas-on-the-display)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Gas team <gas@example.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "billiard-ball gas of the article Gas on the display (1989), in a terminal")
set(CPACK_PACKAGE_DESCRIPTION
    "A handful of hard discs fly across a table in the terminal, computed from one\n\
collision to the next as the article by Bilenkin and Yutkin builds it, in\n\
seven stages. With the teaching scenes (gas crowd, gas hard/corner, ...),\n\
kinetic theory's statistics screen and the manual page.")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR})
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_PROJECT_CONFIG_FILE ${CMAKE_SOURCE_DIR}/stages/program/cpack_checks.cmake)
include(CPack)
