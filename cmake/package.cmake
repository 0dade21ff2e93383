# What an install holds beyond the libraries, the CLI and the Python module: the figure scripts
# as commands, the docs, man pages and bash completion; and the Debian package built from it all
# (cpack -G DEB, or scripts/package).

# The figure scripts as PREFIX/bin/ceilplan-plot-*, importing ceilplan_plots installed beside the
# Python module: an installed script finds it relative to itself, so any prefix works, and so
# does a package unpacked anywhere.
install(FILES scripts/ceilplan_plots.py DESTINATION ${CEILPLAN_PYTHON_INSTALL_DIR})
set(plots_module_dir ${CEILPLAN_PYTHON_INSTALL_DIR})
if(NOT IS_ABSOLUTE ${plots_module_dir})
  file(RELATIVE_PATH plots_module_dir /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${CEILPLAN_PYTHON_INSTALL_DIR})
endif()
set(script_dir_line "sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))")
foreach(script plot-compare plot-coverage plot-current plot-duty plot-tour)
  set(source ${PROJECT_SOURCE_DIR}/scripts/${script})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${source})
  file(READ ${source} text)
  if(text MATCHES "ceilplan_plots" AND NOT text MATCHES "sys\\.path\\.insert\\(0, os\\.path\\.dirname\\(os\\.path\\.abspath")
    message(FATAL_ERROR "scripts/${script} imports ceilplan_plots without the line that finds it: ${script_dir_line}")
  endif()
  string(REPLACE "${script_dir_line}"
                 "sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), \"${plots_module_dir}\"))"
                 text "${text}")
  string(REPLACE "Usage: scripts/${script}" "Usage: ceilplan-${script}" text "${text}")
  file(WRITE ${PROJECT_BINARY_DIR}/installed-scripts/ceilplan-${script} "${text}")
  install(PROGRAMS ${PROJECT_BINARY_DIR}/installed-scripts/ceilplan-${script} DESTINATION ${CMAKE_INSTALL_BINDIR})
endforeach()

# The docs as the source tree has them, so README.md's links to docs/*.md and the pages' figures
# hold: PREFIX/share/doc/ceilplan/{README.md, CHANGELOG.md, LICENSE, docs/}.
install(FILES README.md CHANGELOG.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)

# Man pages and bash completion, written from the built CLI's --help so they cannot drift from it.
if(CEILPLAN_BUILD_CLI)
  find_program(CEILPLAN_HELP2MAN help2man)
  if(NOT CEILPLAN_HELP2MAN)
    message(FATAL_ERROR "help2man not found: it writes the man pages; run scripts/setup (or configure with "
                        "-DCEILPLAN_BUILD_CLI=OFF)")
  endif()
  set(cli_docs ${PROJECT_BINARY_DIR}/cli-docs)
  add_custom_command(
    OUTPUT ${cli_docs}/completions/ceilplan ${cli_docs}/man1/ceilplan.1.gz
    COMMAND ${CMAKE_COMMAND} -E rm -rf ${cli_docs}
    COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/scripts/make-cli-docs $<TARGET_FILE:ceilplan> ${PROJECT_VERSION}
            ${cli_docs} ${CMAKE_INSTALL_DOCDIR}
    DEPENDS ceilplan ${PROJECT_SOURCE_DIR}/scripts/make-cli-docs
    COMMENT "Man pages and bash completion from ceilplan --help")
  add_custom_target(ceilplan_cli_docs ALL DEPENDS ${cli_docs}/completions/ceilplan ${cli_docs}/man1/ceilplan.1.gz)
  install(DIRECTORY ${cli_docs}/man1 DESTINATION ${CMAKE_INSTALL_MANDIR})
  install(FILES ${cli_docs}/completions/ceilplan DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
endif()

# The Debian package: ceilplan_VERSION_ARCH.deb, installed under /usr. Its Depends are the shared
# libraries the CLI and the module link (dpkg-shlibdeps), the interpreter the module was built
# for, and numpy and matplotlib (the module's arrays, the figure commands). The -dev packages
# that find_package(ceilplan) needs to build against it are suggested, not required.
set(CPACK_PACKAGE_NAME ceilplan)
set(CPACK_PACKAGE_VENDOR "the ceilplan developers")
set(CPACK_PACKAGE_CONTACT "the ceilplan developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "battery-wear-aware inspection planning for multirotors flying under ceilings")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3-numpy, python3-matplotlib")
if(CEILPLAN_BUILD_PYTHON)
  math(EXPR next_minor "${CEILPLAN_PYTHON_VERSION_MINOR} + 1")
  string(PREPEND CPACK_DEBIAN_PACKAGE_DEPENDS
         "python3 (>= ${CEILPLAN_PYTHON_VERSION_MAJOR}.${CEILPLAN_PYTHON_VERSION_MINOR}), "
         "python3 (<< ${CEILPLAN_PYTHON_VERSION_MAJOR}.${next_minor}), ")
else()
  string(PREPEND CPACK_DEBIAN_PACKAGE_DEPENDS "python3, ")
endif()
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "cmake, g++, libeigen3-dev, liboctomap-dev, libdynamicedt3d-dev, libompl-dev, libnlopt-cxx-dev, libyaml-cpp-dev, \
nlohmann-json3-dev, libgeographiclib-dev, libminizip-dev, libtinyxml2-dev, libopen3d-dev, libassimp-dev, libproj-dev, \
libssl-dev")
include(CPack)
