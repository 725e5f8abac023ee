# `cmake --install BUILD --prefix DIR`: the user tools in bin/, the firmware
# images in share/minrt/firmware/ (where an installed host-send looks for
# them), and a man page per tool in share/man/man1/, generated at build time
# from the tool's --help and --version by Debian's help2man.
include(GNUInstallDirs)

# tool -> one-line description for the man page's NAME section.
set(MINRT_USER_TOOLS minrt host-send firmware-sim image-compare)
set(_desc_minrt "render min-rt SLD, CS418, Jaworski, miniRT and EASTRAY scenes on the host")
set(_desc_host-send "send a scene to the min-rt firmware over a serial line and receive the image")
set(_desc_firmware-sim "RV32IMF instruction-set simulator for the min-rt firmware")
set(_desc_image-compare "compare two images (PNG, PPM, BMP) with the SPEC.md measures")

install(TARGETS ${MINRT_USER_TOOLS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# miniRT: minrt under the 42 subject's name (host/CMakeLists.txt).
install(CODE "execute_process(COMMAND \${CMAKE_COMMAND} -E create_symlink minrt
              \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/miniRT\")")

# The firmware images the runtime/ build made (empty names: not built).
set(_fw_files "")
foreach(_fw MINRT_FIRMWARE_ELF MINRT_FIRMWARE_SOFTFLOAT_ELF MINRT_FIRMWARE_SMALL_ELF MINRT_FIRMWARE_PROGRAM_BIN)
  if(${_fw})
    list(APPEND _fw_files "${${_fw}}")
  endif()
endforeach()
if(_fw_files)
  install(FILES ${_fw_files} DESTINATION ${CMAKE_INSTALL_DATADIR}/minrt/firmware)
endif()

find_program(MINRT_HELP2MAN help2man)
if(MINRT_HELP2MAN)
  set(_man_dir "${CMAKE_BINARY_DIR}/man/man1")
  set(_pages "")
  foreach(_tool ${MINRT_USER_TOOLS})
    set(_page "${_man_dir}/${_tool}.1")
    add_custom_command(OUTPUT "${_page}"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${_man_dir}"
      COMMAND "${MINRT_HELP2MAN}" --no-info --no-discard-stderr --section 1
              --name "${_desc_${_tool}}" --output "${_page}" "$<TARGET_FILE:${_tool}>"
      DEPENDS ${_tool}
      COMMENT "man page ${_tool}.1 (help2man)"
      VERBATIM)
    list(APPEND _pages "${_page}")
  endforeach()
  add_custom_target(man-pages ALL DEPENDS ${_pages})
  install(FILES ${_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man pages (scripts/setup.sh installs it)")
endif()
