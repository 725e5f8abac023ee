# Toolchain file: bare-metal 32-bit RISC-V with clang and ld.lld.
#
#   cmake -S runtime/firmware -B build-rv \
#     -DCMAKE_TOOLCHAIN_FILE=cmake/riscv32-clang.cmake \
#     [-DMINRT_BOARD=$PWD/boards/murax.board] [-DMINRT_FW_ISA=rv32im]
#
# The ISA flags (-march/-mabi) come from the board file, in
# runtime/firmware/CMakeLists.txt, so that a reconfigure with another board
# takes effect (flags set here stay as the build directory's first configure
# left them). MINRT_CLANG and MINRT_LLD may name the tools; otherwise they
# are searched.
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(_minrt_target riscv32-unknown-elf)
set(_minrt_cpu_flags "-mcmodel=medany")
include(${CMAKE_CURRENT_LIST_DIR}/bare_metal_clang.cmake)
