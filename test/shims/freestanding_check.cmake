# cmake -P script: compile freestanding_tu.cpp for riscv32 and check the
# object's undefined symbols and instructions.
#   CLANGXX, NM, OBJDUMP: tools; SRC: the TU; OBJ: output object;
#   MARCH, MABI: target; CORE_DIR: the repository root (the only include directory);
#   ALLOWED_UNDEF: regex every undefined symbol must match ("" = none allowed);
#   FORBIDDEN_INSNS: regex of mnemonics that must not appear in the code.
execute_process(
  COMMAND ${CLANGXX} --target=riscv32-unknown-elf -march=${MARCH} -mabi=${MABI}
          -ffreestanding -fno-exceptions -fno-rtti -std=c++20 -O2
          -ffp-contract=off -I${CORE_DIR} -c ${SRC} -o ${OBJ}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "compile failed (${MARCH}):\n${out}${err}")
endif()

execute_process(COMMAND ${NM} -u ${OBJ} RESULT_VARIABLE rc OUTPUT_VARIABLE undef)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed")
endif()
string(REGEX MATCHALL "[^ \t\r\n]+\n" lines "${undef}")
set(bad "")
foreach(line IN LISTS lines)
  string(STRIP "${line}" sym)
  if(sym STREQUAL "U")
    continue()
  endif()
  if(ALLOWED_UNDEF STREQUAL "" OR NOT sym MATCHES "${ALLOWED_UNDEF}")
    list(APPEND bad "${sym}")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "${MARCH}: unexpected undefined symbols: ${bad}")
endif()
message(STATUS "${MARCH}: undefined symbols:\n${undef}")

if(FORBIDDEN_INSNS)
  execute_process(COMMAND ${OBJDUMP} -d ${OBJ} RESULT_VARIABLE rc OUTPUT_VARIABLE dis)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} failed")
  endif()
  string(REGEX MATCHALL "\t(${FORBIDDEN_INSNS})[ \t\n]" hits "${dis}")
  if(hits)
    message(FATAL_ERROR "${MARCH}: forbidden instructions: ${hits}")
  endif()
  string(REGEX MATCHALL "\tf(add|sub|mul|div)\\.s" fpu "${dis}")
  list(LENGTH fpu nfpu)
  message(STATUS "${MARCH}: ${nfpu} float add/sub/mul/div instructions, none forbidden")
endif()
