# Installation layout and the Debian package (CPack):
#     cmake --build build --target package   ->   build/drivedesk_VERSION_amd64.deb
# The programs need no data files at run time: translations (.qm), parameter dictionaries
# and alarm tables are compiled into them as Qt resources (ui/CMakeLists.txt,
# app/CMakeLists.txt, resources/core.qrc). Installed beside them: the desktop entry, icons,
# AppStream metainfo, the MIME types, manual pages (help2man), bash completion, the licence
# and the Debian copyright and changelog. See docs/packaging.md.
include(GNUInstallDirs)

set(DRIVEDESK_APP_ID "io.github.drivedesk.DriveDesk")
set(DRIVEDESK_HOMEPAGE_URL "https://github.com/drivedesk/drivedesk" CACHE STRING
    "The project page named in the AppStream metainfo")
set(DRIVEDESK_SCREENSHOT_URL "https://raw.githubusercontent.com/drivedesk/drivedesk/main/docs/screenshots"
    CACHE STRING "Where docs/screenshots/ is published (AppStream screenshots)")
set(pkg "${PROJECT_SOURCE_DIR}/packaging")
set(docdir "${CMAKE_INSTALL_DATAROOTDIR}/doc/drivedesk")

# --- the programs ---------------------------------------------------------------------------
set(programs drivedesk-cli drivedesk-sim)
if(DRIVEDESK_BUILD_GUI)
  list(PREPEND programs drivedesk)
endif()
install(TARGETS ${programs} RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# --- desktop integration --------------------------------------------------------------------
if(DRIVEDESK_BUILD_GUI)
  install(FILES "${pkg}/desktop/${DRIVEDESK_APP_ID}.desktop"
          DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/applications")
  configure_file("${pkg}/desktop/${DRIVEDESK_APP_ID}.metainfo.xml.in"
                 "${PROJECT_BINARY_DIR}/packaging/${DRIVEDESK_APP_ID}.metainfo.xml" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/packaging/${DRIVEDESK_APP_ID}.metainfo.xml"
          DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/metainfo")
  install(FILES "${pkg}/desktop/drivedesk.xml" DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/mime/packages")
  install(FILES "${pkg}/icons/drivedesk.svg" DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/icons/hicolor/scalable/apps"
          RENAME "${DRIVEDESK_APP_ID}.svg")
  foreach(size 16 22 24 32 48 64 128 256)
    install(FILES "${pkg}/icons/drivedesk-${size}.png"
            DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/icons/hicolor/${size}x${size}/apps"
            RENAME "${DRIVEDESK_APP_ID}.png")
  endforeach()
endif()

# --- bash completion: parameter keys of the bundled dictionaries --------------------------
set(completion_params "")
foreach(family servo-can servo-modbus shuoke)
  set(dict "${PROJECT_SOURCE_DIR}/resources/dictionaries/${family}.json")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${dict}")
  file(READ "${dict}" json)
  string(JSON count LENGTH "${json}" parameters)
  set(keys "")
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON key GET "${json}" parameters ${i} key)
    string(APPEND keys " ${key}")
  endforeach()
  string(STRIP "${keys}" keys)
  string(APPEND completion_params "    [${family}]=\"${keys}\"\n")
endforeach()
string(STRIP "${completion_params}" DRIVEDESK_COMPLETION_PARAMS)
string(PREPEND DRIVEDESK_COMPLETION_PARAMS "    ")
configure_file("${pkg}/completion/drivedesk-cli.bash.in" "${PROJECT_BINARY_DIR}/packaging/drivedesk-cli" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/packaging/drivedesk-cli"
        DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/bash-completion/completions")

# --- manual pages, from each program's --help (help2man) ---------------------------------
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(man_names
      "drivedesk|commissioning and tuning workbench for servo and stepper drives|--lang=en|"
      "drivedesk|伺服与步进驱动器调试整定工作台|--lang=zh_CN|zh_CN"
      "drivedesk-cli|commission servo and stepper drives from scripts|--lang=en|"
      "drivedesk-cli|在脚本中调试伺服与步进驱动器|--lang=zh_CN|zh_CN"
      "drivedesk-sim|simulated servo and stepper drives on a pty or a CAN bus||")
  set(man_outputs "")
  foreach(entry ${man_names})
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 program)
    list(GET fields 1 name)
    list(GET fields 2 lang_arg)
    list(GET fields 3 locale)
    if(NOT DRIVEDESK_BUILD_GUI AND program STREQUAL "drivedesk")
      continue()
    endif()
    set(dir "${PROJECT_BINARY_DIR}/packaging/man/${locale}")
    set(out "${dir}/${program}.1.gz")
    add_custom_command(
      OUTPUT "${out}"
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${dir}"
      COMMAND "${CMAKE_COMMAND}" "-DHELP2MAN=${HELP2MAN}" "-DPROGRAM=$<TARGET_FILE:${program}>" "-DNAME=${name}"
              "-DOUTPUT=${out}" "-DLANG_ARG=${lang_arg}" "-DINCLUDE=${pkg}/man/see-also.h2m"
              -P "${PROJECT_SOURCE_DIR}/cmake/ManPage.cmake"
      DEPENDS ${program} "${PROJECT_SOURCE_DIR}/cmake/ManPage.cmake" "${pkg}/man/see-also.h2m"
      COMMENT "Manual page ${locale} ${program}.1"
      VERBATIM)
    list(APPEND man_outputs "${out}")
    install(FILES "${out}" DESTINATION "${CMAKE_INSTALL_MANDIR}/${locale}/man1")
  endforeach()
  add_custom_target(drivedesk_manpages ALL DEPENDS ${man_outputs})
else()
  message(STATUS "help2man not found: no manual pages (packaging/install-deps.sh installs it)")
endif()

# --- licence, copyright, changelog ---------------------------------------------------------
install(FILES "${pkg}/debian/copyright" "${PROJECT_SOURCE_DIR}/README.md" DESTINATION "${docdir}")
set(changelog "${PROJECT_BINARY_DIR}/packaging/changelog.gz")
add_custom_command(
  OUTPUT "${changelog}"
  COMMAND gzip -9n -c "${pkg}/debian/changelog" > "${changelog}"
  DEPENDS "${pkg}/debian/changelog"
  COMMENT "Compressing the package changelog")
add_custom_target(drivedesk_changelog ALL DEPENDS "${changelog}")
install(FILES "${changelog}" DESTINATION "${docdir}")

# --- the Debian package ----------------------------------------------------------------------
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "drivedesk")
set(CPACK_PACKAGE_VENDOR "DriveDesk contributors")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "DriveDesk maintainers <maintainers@drivedesk.invalid>")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # drivedesk_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "electronics")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${DRIVEDESK_HOMEPAGE_URL}")
# Libraries from the binaries (dpkg-shlibdeps); what is loaded at run time as a plugin is
# named here: the window system plugins (xcb, wayland, offscreen) for the workbench.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
# Qt's own Chinese texts (standard dialogs); bash-completion for the completion file.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "bash-completion")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "commissioning and tuning tool for servo and stepper drives")
# The synopsis is CPACK_PACKAGE_DESCRIPTION_SUMMARY; CPack indents these lines and turns the
# empty one into " .".
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "DriveDesk finds servo and stepper drives on an RS485, RS232 or CAN bus, reads
and edits their parameters, runs EEPROM operations, backs parameters up to a
file and restores them, plots live trends, jogs the axis safely and reads and
clears alarms. Drive families: AC servo drives on CAN and on Modbus RTU, and
Shuoke M6505/M4505 stepper drives.

The package contains the workbench (drivedesk), the same work for scripts
(drivedesk-cli) and a drive simulator on a pseudo-terminal or a CAN bus
(drivedesk-sim). The user interface is in English and Chinese.")
include(CPack)
