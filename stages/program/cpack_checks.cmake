# Read by cpack before it makes a package (CPACK_PROJECT_CONFIG_FILE in
# install.cmake). Without dpkg-shlibdeps (Debian's dpkg-dev) or `file`,
# CPack would make a .deb that declares no dependencies at all, which then
# installs on a machine without libfmt9 and fails there: refuse instead.
# Not one of the article's stages; the reference: README.md ("Installing").
if(CPACK_GENERATOR STREQUAL "DEB")
  find_program(GAS_SHLIBDEPS dpkg-shlibdeps)
  find_program(GAS_FILE file)
  if(NOT GAS_SHLIBDEPS OR NOT GAS_FILE)
    message(FATAL_ERROR "a Debian package needs dpkg-shlibdeps and file to declare its "
                        "dependencies: apt-get install dpkg-dev file")
  endif()
endif()
