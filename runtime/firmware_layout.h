/* Layout constants of the firmware image, shared by the linker script
 * (firmware.ld.S), crt0.S and the C++ runtime. Plain #defines without
 * suffixes so the linker script and the assembler can use them.
 *
 *   MINRT_RAM_BASE  .text .rodata .data .bss | arena ... | stack | boot args
 *                                                     RAM end ^
 */
#ifndef MINRT_FIRMWARE_LAYOUT_H
#define MINRT_FIRMWARE_LAYOUT_H

#include <minrt/boot_args.h>

/* Stack bytes below __stack_top. The measured high-water mark for
 * contest.sld at 512x512 is in docs/firmware.md; keep a wide margin. */
#define MINRT_FW_STACK_SIZE 0x8000

/* Kept free at the top of RAM for the argument block firmware-sim writes. */
#define MINRT_FW_BOOT_ARGS_RESERVE MINRT_BOOT_ARGS_MAX

/* crt0 fills the stack with this word; the footprint report finds the
 * deepest word that no longer holds it. */
#define MINRT_FW_STACK_PATTERN 0x5ca1ab1e

#endif
