/* Linker script of the firmware, preprocessed with `clang -E -P -x c` so the
 * addresses come from include/minrt/memory_map.h and firmware_layout.h.
 * One RAM region; the ELF loader (firmware-sim, QEMU -kernel) puts every
 * section at its final address.
 *
 * With -DMINRT_LINK_PROGRAM the image starts at MINRT_PROGRAM_LOAD_ADDR
 * instead: a program for the course protocol's boot stage, uploaded as the
 * flat binary of .text/.rodata/.data (llvm-objcopy -O binary). */
#include <minrt/memory_map.h>
#include "firmware_layout.h"


OUTPUT_ARCH(riscv)
ENTRY(_start)

#ifdef MINRT_LINK_PROGRAM
#define MINRT_IMAGE_BASE MINRT_PROGRAM_LOAD_ADDR
#else
#define MINRT_IMAGE_BASE MINRT_RAM_BASE
#endif

MEMORY
{
  RAM (rwx) : ORIGIN = MINRT_IMAGE_BASE, LENGTH = MINRT_RAM_BASE + MINRT_RAM_DEFAULT_SIZE - MINRT_IMAGE_BASE
}

SECTIONS
{
  .text : {
    __text_start = .;
    KEEP(*(.text.init))
    *(.text .text.*)
    __text_end = .;
  } > RAM

  .rodata : ALIGN(16) {
    __rodata_start = .;
    *(.rodata .rodata.* .srodata .srodata.*)
    . = ALIGN(4);
    __init_array_start = .;
    KEEP(*(SORT(.init_array.*)))
    KEEP(*(.init_array))
    __init_array_end = .;
    __rodata_end = .;
  } > RAM

  /* Loaded in place: LOADADDR equals ADDR, so crt0's copy loop finds nothing
   * to do. A board with ROM would put `AT> ROM` here. */
  .data : ALIGN(16) {
    __data_start = .;
    *(.data .data.* .sdata .sdata.*)
    . = ALIGN(4);
    __data_end = .;
  } > RAM
  __data_load_start = LOADADDR(.data);

  .bss (NOLOAD) : ALIGN(16) {
    __bss_start = .;
    *(.sbss .sbss.* .bss .bss.* COMMON)
    . = ALIGN(4);
    __bss_end = .;
  } > RAM

  /* Everything between .bss and the stack is the render arena. */
  __arena_start = ALIGN(__bss_end, 16);
  __stack_top = ORIGIN(RAM) + LENGTH(RAM) - MINRT_FW_BOOT_ARGS_RESERVE;
  __stack_bottom = __stack_top - MINRT_FW_STACK_SIZE;
  __arena_end = __stack_bottom;
  ASSERT(__arena_end > __arena_start, "the image leaves no room for the arena and the stack")
#ifdef MINRT_LINK_PROGRAM
  ASSERT(__data_end - ORIGIN(RAM) <= MINRT_PROGRAM_MAX_SIZE, "the program's code and data exceed MINRT_PROGRAM_MAX_SIZE")
#else
  /* The boot stage writes an uploaded program there while it runs. */
  ASSERT(__bss_end <= MINRT_PROGRAM_LOAD_ADDR, "the resident image reaches into the program region")
  ASSERT(MINRT_PROGRAM_LOAD_ADDR + MINRT_PROGRAM_MAX_SIZE <= __stack_bottom, "the program region reaches the stack")
#endif

  /DISCARD/ : { *(.eh_frame .eh_frame_hdr .comment .note .note.*) }
}
