# A firmware ELF under QEMU (QEMU_ARGS: the machine's options, ';'-separated)
# renders SCENE at its built-in size to the bytes of
# `minrt --precision float --shims portable` at SIZE, and exits 0. Without
# the QEMU binary it stops with a message the test's
# SKIP_REGULAR_EXPRESSION turns into "skipped".
#   cmake -DQEMU=... "-DQEMU_ARGS=-M;mps2-an386;..." -DHOST=minrt -DELF=... -DSCENE=... \
#         -DSIZE=32x32 -DWORK=dir -P run_qemu_image.cmake
if(NOT QEMU)
  message(FATAL_ERROR "${QEMU_NAME} not found: install it (scripts/setup.sh) to run this image")
endif()
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(name "${SCENE}" NAME_WE)
get_filename_component(elf_name "${ELF}" NAME_WE)
set(out "${WORK}/${elf_name}-${name}.ppm")
set(ref "${WORK}/${elf_name}-${name}-host.ppm")
execute_process(
  COMMAND "${QEMU}" ${QEMU_ARGS} -nographic -monitor none -serial stdio -kernel "${ELF}"
  INPUT_FILE "${SCENE}" OUTPUT_FILE "${out}" ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${QEMU}: status ${rc}: ${err}")
endif()
execute_process(COMMAND "${HOST}" --precision float --shims portable --size ${SIZE} "${SCENE}"
                OUTPUT_FILE "${ref}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "minrt: status ${rc}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${ref}" "${out}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the image ${out} differs from the host's ${ref}")
endif()
file(SIZE "${out}" n)
message(STATUS "${name} ${SIZE}: ${elf_name} in QEMU and the host float model agree, ${n} bytes")
file(REMOVE "${out}" "${ref}")
