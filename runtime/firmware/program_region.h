/* Preprocessed at configure time by CMakeLists.txt: the size of the board's
 * program region, to decide whether the boot-stage programs are linked. */
#include <minrt/memory_map.h>
MINRT_PROGRAM_MAX_SIZE
