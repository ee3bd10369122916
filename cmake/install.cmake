# SPDX-License-Identifier: Apache-2.0
# What `cmake --install BUILD --prefix P` puts where (the .deb packs the same, cmake/package_deb.cmake):
#
#   bin/ifsfx                                   the command (render to PNG itself)   runtime
#   libexec/ifsfx/ifsfx-full                    every command; bin/ifsfx execs it    runtime
#   share/man/man1/ifsfx.1                      man page, from the real --help texts runtime
#   share/bash-completion/completions/ifsfx     bash completion, from the same       runtime
#   share/ifsfx/presets/                        copies of the shipped presets        runtime
#   share/doc/ifsfx/README.md, docs/            the README and the pages it links    runtime
#   share/doc/ifsfx/copyright                   Debian copyright (cmake/debian-copyright) runtime
#   share/doc/ifsfx-dev/copyright               the same, for the -dev package        dev
#   include/ifsfx/{ifs,superifs,collage,fractaldb,engine,video}/ public headers (not detail/)         dev
#   LIBDIR/libifsfx_{ifs,superifs,collage,fractaldb,engine,video}.a                                dev
#   LIBDIR/cmake/ifsfx/                         find_package(ifsfx CONFIG)           dev
#   LIBDIR/pkgconfig/ifsfx.pc                   pkg-config --cflags --libs ifsfx     dev
#
# LIBDIR is GNUInstallDirs' CMAKE_INSTALL_LIBDIR: lib, or lib/x86_64-linux-gnu for prefix /usr.
# bin/ifsfx finds ifsfx-full by the path from BINDIR to LIBEXECDIR fixed at configure time
# (cli/CMakeLists.txt), so the two move together under any prefix.
# The presets are built into the program (cmake/embed_presets.cmake); the copies are there to be
# read, copied and changed (`ifsfx render my-fern.toml`), like a package's examples.
#
# Headers keep their in-tree paths under include/ifsfx/, which is the include directory the
# package and ifsfx.pc give: consumers write #include "ifs/steal_map.h", as the project's own code.
#
# Components: `runtime` is the default of every install() rule (CMAKE_INSTALL_DEFAULT_COMPONENT_NAME,
# set in the top CMakeLists.txt) and is the `ifsfx` .deb; `dev` is the `ifsfx-dev` .deb. To ship
# something more in the ifsfx package, e.g. the frei0r plugins, write an install() rule next to its
# target, without COMPONENT:
#   install(TARGETS ifsfx_frei0r LIBRARY DESTINATION lib/frei0r-1)
# The package test (`deb` in tests/install/install_test.sh) lists files it expects: add the
# new ones there. Their shared-library dependencies reach Depends through dpkg-shlibdeps.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IFSFX_LIBRARIES)
foreach(lib ifs superifs collage fractaldb flame engine video)
  if(TARGET ${lib})
    list(APPEND IFSFX_LIBRARIES ${lib})
    # libifsfx_video.a, not libvideo.a, once it lies beside every other library of the system.
    set_target_properties(${lib} PROPERTIES OUTPUT_NAME ifsfx_${lib})
  endif()
endforeach()

# ---- the command, its man page and completion ----------------------------------------------------
install(TARGETS ifsfx RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ifsfx_full RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/ifsfx)

set(IFSFX_MAN_PAGE ${PROJECT_BINARY_DIR}/doc/ifsfx.1)
set(IFSFX_COMPLETION ${PROJECT_BINARY_DIR}/doc/ifsfx.bash-completion)
add_custom_command(
  OUTPUT ${IFSFX_MAN_PAGE} ${IFSFX_COMPLETION}
  COMMAND sh ${PROJECT_SOURCE_DIR}/cmake/cli_docs.sh $<TARGET_FILE:ifsfx_full> ${PROJECT_VERSION}
          ${IFSFX_MAN_PAGE} ${IFSFX_COMPLETION}
  DEPENDS ifsfx_full ${PROJECT_SOURCE_DIR}/cmake/cli_docs.sh
  COMMENT "Writing the man page and bash completion from ifsfx-full --help"
  VERBATIM)
add_custom_target(ifsfx_cli_docs ALL DEPENDS ${IFSFX_MAN_PAGE} ${IFSFX_COMPLETION})
install(FILES ${IFSFX_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${IFSFX_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        RENAME ifsfx)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/presets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ifsfx/presets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/studio/web/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ifsfx/studio)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
# Debian wants /usr/share/doc/PACKAGE/copyright in every package: the machine-readable copyright
# file (format 1.0, Apache-2.0, as LICENSE) goes into both, under each package's name.
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian-copyright DESTINATION ${CMAKE_INSTALL_DOCDIR}
        RENAME copyright)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian-copyright
        DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/ifsfx-dev RENAME copyright COMPONENT dev)

# ---- the libraries: headers, archives, CMake package, pkg-config ---------------------------------
install(TARGETS ${IFSFX_LIBRARIES} EXPORT ifsfxTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        FILE_SET HEADERS DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ifsfx COMPONENT dev)
set(IFSFX_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ifsfx)
install(EXPORT ifsfxTargets NAMESPACE ifsfx:: DESTINATION ${IFSFX_CMAKE_DIR} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ifsfxConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ifsfxConfig.cmake
                              INSTALL_DESTINATION ${IFSFX_CMAKE_DIR})
# 0.x: a minor release may change the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ifsfxConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ifsfxConfig.cmake ${PROJECT_BINARY_DIR}/ifsfxConfigVersion.cmake
        DESTINATION ${IFSFX_CMAKE_DIR} COMPONENT dev)

# ifsfx.pc names its prefix relative to its own folder (${pcfiledir}), so it is right wherever the
# tree is installed: --prefix P, a DESTDIR, or the .deb.
set(pc_dir ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(IS_ABSOLUTE ${CMAKE_INSTALL_LIBDIR})
  set(IFSFX_PC_PREFIX ${CMAKE_INSTALL_PREFIX})
else()
  file(RELATIVE_PATH up /prefix/${pc_dir} /prefix)
  string(REGEX REPLACE "/$" "" up "${up}")
  set(IFSFX_PC_PREFIX "\${pcfiledir}/${up}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE ${CMAKE_INSTALL_${dir}})
    set(IFSFX_PC_${dir} ${CMAKE_INSTALL_${dir}})
  else()
    set(IFSFX_PC_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
# Static libraries: every library they use goes into Libs/Requires (not *.private), or a plain
# `pkg-config --libs ifsfx` would not link. Dependent libraries come first.
set(IFSFX_PC_LIBS)
foreach(lib video engine flame fractaldb collage superifs ifs)
  if(lib IN_LIST IFSFX_LIBRARIES)
    string(APPEND IFSFX_PC_LIBS " -lifsfx_${lib}")
  endif()
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/ifsfx.pc.in ${PROJECT_BINARY_DIR}/ifsfx.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/ifsfx.pc DESTINATION ${pc_dir} COMPONENT dev)
