# include/minrt/board.h (what the host tools and firmware-sim see) must be
# exactly what cmake/minrt_board.cmake generates from boards/qemu-virt.board.
#   cmake -DSOURCE_DIR=<repo> -DWORK=<dir> -P check_reference_header.cmake
include("${SOURCE_DIR}/cmake/minrt_board.cmake")
minrt_read_board("${SOURCE_DIR}/boards/qemu-virt.board" REF)
file(REMOVE "${WORK}/reference_board.h")
minrt_write_board_header(REF "${WORK}/reference_board.h")
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK}/reference_board.h"
                        "${SOURCE_DIR}/include/minrt/board.h" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "include/minrt/board.h is not what boards/qemu-virt.board gives; regenerate it with\n"
                      "  cmake -DBOARD=boards/qemu-virt.board -DOUT=include/minrt/board.h -P cmake/minrt_board.cmake")
endif()
