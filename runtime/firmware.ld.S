/* Linker script of the firmware, preprocessed with `clang -E -P -x c` so the
 * addresses come from include/minrt/memory_map.h (the board's map, generated
 * from its board file) and firmware_layout.h.
 *
 * Code starts at the board's reset address: in ROM when the board has a
 * separate instruction memory (rom_base/rom_size; .data is then copied to
 * RAM by crt0), otherwise in RAM, where the loader (firmware-sim, QEMU
 * -kernel, a $readmemh image) puts every section at its final address.
 *
 * With -DMINRT_LINK_PROGRAM the image starts at MINRT_PROGRAM_LOAD_ADDR
 * instead: a program for the course protocol's boot stage, uploaded as the
 * flat binary of .text/.rodata/.data (llvm-objcopy -O binary). */
#include <minrt/memory_map.h>
#include "firmware_layout.h"


/* The Cortex-M port (runtime/cortex-m/) links with this script too. */
#ifdef MINRT_LINK_ARM
OUTPUT_ARCH(arm)
ENTRY(minrt_reset)
#else
OUTPUT_ARCH(riscv)
ENTRY(_start)
#endif

#ifdef MINRT_LINK_PROGRAM
#define MINRT_IMAGE_BASE MINRT_PROGRAM_LOAD_ADDR
#else
#define MINRT_IMAGE_BASE MINRT_BOARD_RESET
#endif

#if defined(MINRT_BOARD_ROM_BASE) && !defined(MINRT_LINK_PROGRAM)
#define MINRT_CODE ROM
MEMORY
{
  ROM (rx) : ORIGIN = MINRT_IMAGE_BASE, LENGTH = MINRT_BOARD_ROM_BASE + MINRT_BOARD_ROM_SIZE - MINRT_IMAGE_BASE
  RAM (rwx) : ORIGIN = MINRT_RAM_BASE, LENGTH = MINRT_RAM_DEFAULT_SIZE
}
#else
#define MINRT_CODE RAM
MEMORY
{
  RAM (rwx) : ORIGIN = MINRT_IMAGE_BASE, LENGTH = MINRT_RAM_BASE + MINRT_RAM_DEFAULT_SIZE - MINRT_IMAGE_BASE
}
#endif

SECTIONS
{
  .text : {
    __text_start = .;
    KEEP(*(.text.init))
    *(.text .text.*)
    __text_end = .;
  } > MINRT_CODE

  .rodata : ALIGN(16) {
    __rodata_start = .;
    *(.rodata .rodata.* .srodata .srodata.*)
    . = ALIGN(4);
    __init_array_start = .;
    KEEP(*(SORT(.init_array.*)))
    KEEP(*(.init_array))
    __init_array_end = .;
    __rodata_end = .;
  } > MINRT_CODE

  /* Without ROM loaded in place: LOADADDR equals ADDR, so crt0's copy loop
   * finds nothing to do. With ROM its initial values follow .rodata there. */
  .data : ALIGN(16) {
    __data_start = .;
    *(.data .data.* .sdata .sdata.*)
    . = ALIGN(4);
    __data_end = .;
  } > RAM AT> MINRT_CODE
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
#elif MINRT_PROGRAM_MAX_SIZE > 0
  /* The boot stage writes an uploaded program there while it runs. */
  ASSERT(__bss_end <= MINRT_PROGRAM_LOAD_ADDR, "the resident image reaches into the program region")
  ASSERT(MINRT_PROGRAM_LOAD_ADDR + MINRT_PROGRAM_MAX_SIZE <= __stack_bottom, "the program region reaches the stack")
#endif

  /DISCARD/ : { *(.eh_frame .eh_frame_hdr .comment .note .note.* .ARM.exidx .ARM.exidx.* .ARM.extab .ARM.extab.*) }
}
