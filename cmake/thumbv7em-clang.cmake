# Toolchain file: bare-metal ARM Cortex-M4 with its single-precision FPU
# (thumbv7em, hard-float ABI) with clang and ld.lld, for the Cortex-M port
# (runtime/cortex-m/, docs/porting.md):
#
#   cmake -S runtime/cortex-m -B build-m4 -DCMAKE_TOOLCHAIN_FILE=$PWD/cmake/thumbv7em-clang.cmake
set(CMAKE_SYSTEM_PROCESSOR arm)
set(_minrt_target thumbv7em-none-eabihf)
set(_minrt_cpu_flags "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb")
include(${CMAKE_CURRENT_LIST_DIR}/bare_metal_clang.cmake)
