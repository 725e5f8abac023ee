# One firmware test case, run by ctest as `cmake -D... -P run_firmware_case.cmake`.
#
# MODE=host  : the firmware ELF in firmware-sim must print exactly what the host
#              build `minrt --precision float --shims portable` prints for SCENE
#              at SIZE; where the host rejects the scene, the firmware must send
#              one MINRT_ERROR_MARKER line, no image, and stop with status 2.
#              EXPECT=error additionally requires the host to reject it.
# MODE=qemu  : ELF (built with a small default size, since QEMU passes no
#              arguments) under qemu-system-riscv32 -M virt must print the same
#              bytes as in firmware-sim without arguments, and exit 0.
#
# Inputs: MODE SIM ELF SCENE WORK MARKER [HOST SIZE EXPECT FORMAT] [QEMU]
cmake_minimum_required(VERSION 3.20)

foreach(v MODE SIM ELF SCENE WORK MARKER)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_firmware_case: ${v} not set")
  endif()
endforeach()
if(NOT FORMAT)
  set(FORMAT p3)
endif()
if(NOT EXISTS "${SCENE}")
  message(FATAL_ERROR "scene ${SCENE} missing")
endif()
if(NOT EXISTS "${ELF}")
  message(FATAL_ERROR "firmware ${ELF} missing (build the `firmware` target)")
endif()

get_filename_component(name "${SCENE}" NAME_WE)
get_filename_component(elf_name "${ELF}" NAME_WE)
set(prefix "${WORK}/${elf_name}-${name}-${SIZE}-${FORMAT}")
file(MAKE_DIRECTORY "${WORK}")

# Fails unless the two output files are identical; removes them when they are.
function(require_same_output expected actual what)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${expected}" "${actual}"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} differ: ${actual} vs ${expected}")
  endif()
  file(SIZE "${actual}" n)
  file(REMOVE "${expected}" "${actual}")
  message(STATUS "${name} ${SIZE}: ${what} are identical, ${n} bytes")
endfunction()

if(MODE STREQUAL "qemu")
  execute_process(
    COMMAND "${QEMU}" -M virt -bios none -kernel "${ELF}" -nographic -monitor none -serial stdio
    INPUT_FILE "${SCENE}" OUTPUT_FILE "${prefix}.qemu.ppm" ERROR_VARIABLE qemu_err
    RESULT_VARIABLE qemu_rc TIMEOUT 300)
  execute_process(
    COMMAND "${SIM}" --uart-in "${SCENE}" --uart-out "${prefix}.sim.ppm" "${ELF}"
    RESULT_VARIABLE sim_rc ERROR_VARIABLE sim_err)
  if(NOT qemu_rc EQUAL 0 OR NOT sim_rc EQUAL 0)
    message(FATAL_ERROR "exit status: qemu ${qemu_rc} (${qemu_err}), firmware-sim ${sim_rc} (${sim_err})")
  endif()
  require_same_output("${prefix}.sim.ppm" "${prefix}.qemu.ppm" "QEMU and firmware-sim outputs")
  return()
endif()

if(NOT MODE STREQUAL "host")
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()

execute_process(
  COMMAND "${HOST}" -q --size ${SIZE} --format ${FORMAT} --precision float --shims portable "${SCENE}"
  OUTPUT_FILE "${prefix}.host.ppm" ERROR_VARIABLE host_err RESULT_VARIABLE host_rc)
execute_process(
  COMMAND "${SIM}" --uart-in "${SCENE}" --uart-out "${prefix}.fw.out" "${ELF}" -- --size ${SIZE} --format ${FORMAT}
  RESULT_VARIABLE fw_rc ERROR_VARIABLE fw_err)

if(host_rc EQUAL 0)
  if(EXPECT STREQUAL "error")
    message(FATAL_ERROR "the host build accepts ${SCENE}, expected a rejection")
  endif()
  if(NOT fw_rc EQUAL 0)
    file(READ "${prefix}.fw.out" head LIMIT 300)
    message(FATAL_ERROR "firmware exit status ${fw_rc} (${fw_err}); output starts: ${head}")
  endif()
  require_same_output("${prefix}.host.ppm" "${prefix}.fw.out" "firmware and host images")
  return()
endif()

# The host rejected the scene: the firmware must too, with one marker line.
file(READ "${prefix}.fw.out" out)
string(LENGTH "${MARKER}" marker_length)
string(SUBSTRING "${out}" 0 ${marker_length} start)
string(REGEX MATCHALL "\n" newlines "${out}")
list(LENGTH newlines line_count)
string(REGEX MATCH "\n$" ends_with_newline "${out}")
if(NOT fw_rc EQUAL 2)
  message(FATAL_ERROR "firmware exit status ${fw_rc}, expected 2 (${fw_err}); output: ${out}")
endif()
if(NOT start STREQUAL MARKER OR NOT line_count EQUAL 1 OR NOT ends_with_newline)
  message(FATAL_ERROR "expected exactly one line starting with '${MARKER}', got: ${out}")
endif()
file(REMOVE "${prefix}.host.ppm" "${prefix}.fw.out")
string(STRIP "${out}" out)
message(STATUS "${name}: rejected as by the host: ${out}")
