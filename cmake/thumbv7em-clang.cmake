# Toolchain file: bare-metal ARM Cortex-M4 with its single-precision FPU
# (thumbv7em, hard-float ABI) with clang and ld.lld, for the Cortex-M port
# (runtime/cortex-m/, docs/porting.md):
#
#   cmake -S runtime/cortex-m -B build-m4 -DCMAKE_TOOLCHAIN_FILE=$PWD/cmake/thumbv7em-clang.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

find_program(MINRT_CLANG NAMES clang clang-14 REQUIRED)
find_program(MINRT_LLD NAMES ld.lld ld.lld-14 REQUIRED)
get_filename_component(_minrt_clang_dir "${MINRT_CLANG}" DIRECTORY)
find_program(MINRT_CLANGXX NAMES clang++ clang++-14 HINTS "${_minrt_clang_dir}" REQUIRED)

set(_minrt_target thumbv7em-none-eabihf)
set(CMAKE_C_COMPILER "${MINRT_CLANG}")
set(CMAKE_CXX_COMPILER "${MINRT_CLANGXX}")
set(CMAKE_ASM_COMPILER "${MINRT_CLANG}")
set(CMAKE_C_COMPILER_TARGET ${_minrt_target})
set(CMAKE_CXX_COMPILER_TARGET ${_minrt_target})
set(CMAKE_ASM_COMPILER_TARGET ${_minrt_target})
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(_minrt_common
    "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb -ffreestanding -nostdlib -ffp-contract=off -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${_minrt_common}")
set(CMAKE_ASM_FLAGS_INIT "${_minrt_common}")
set(CMAKE_CXX_FLAGS_INIT "${_minrt_common} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_EXE_LINKER_FLAGS_INIT "--ld-path=${MINRT_LLD} -nostdlib -static -Wl,--gc-sections")
foreach(_lang C CXX ASM)
  set(CMAKE_${_lang}_FLAGS_RELEASE "-O3 -DNDEBUG" CACHE STRING "")
endforeach()

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
