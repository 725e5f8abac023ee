# The Cortex-M4 port in qemu-system-arm -M mps2-an386 renders SCENE at its
# built-in size to the bytes of `minrt --precision float --shims portable`
# at SIZE, and exits 0 through semihosting. Without qemu-system-arm it stops
# with a message the test's SKIP_REGULAR_EXPRESSION turns into "skipped".
#   cmake -DQEMU=... -DHOST=minrt -DELF=... -DSCENE=... -DSIZE=32x32 -DWORK=dir -P run_cortex_m.cmake
if(NOT QEMU)
  message(FATAL_ERROR "qemu-system-arm not found: install it (scripts/setup.sh) to run the Cortex-M port")
endif()
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(name "${SCENE}" NAME_WE)
set(out "${WORK}/cortex-m4-${name}.ppm")
set(ref "${WORK}/cortex-m4-${name}-host.ppm")
execute_process(
  COMMAND "${QEMU}" -M mps2-an386 -nographic -monitor none -serial stdio
          -semihosting-config enable=on,target=native -kernel "${ELF}"
  INPUT_FILE "${SCENE}" OUTPUT_FILE "${out}" ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "qemu-system-arm: status ${rc}: ${err}")
endif()
execute_process(COMMAND "${HOST}" --precision float --shims portable --size ${SIZE} "${SCENE}"
                OUTPUT_FILE "${ref}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "minrt: status ${rc}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${ref}" "${out}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the Cortex-M4 image ${out} differs from the host's ${ref}")
endif()
file(SIZE "${out}" n)
message(STATUS "${name} ${SIZE}: Cortex-M4 in QEMU and the host float model agree, ${n} bytes")
file(REMOVE "${out}" "${ref}")
