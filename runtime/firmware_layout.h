/* Layout constants of the firmware image, shared by the linker script
 * (firmware.ld.S), crt0.S and the C++ runtime. Plain #defines without
 * suffixes so the linker script and the assembler can use them.
 *
 *   MINRT_RAM_BASE  .text .rodata .data .bss | arena ... | stack | boot args
 *                                                     RAM end ^
 */
#ifndef MINRT_FIRMWARE_LAYOUT_H
#define MINRT_FIRMWARE_LAYOUT_H

/* Stack bytes below __stack_top. The measured high-water mark for
 * contest.sld at 512x512 is in docs/firmware.md; keep a wide margin. */
#define MINRT_FW_STACK_SIZE 0x8000

/* Kept free at the top of RAM for the argument block firmware-sim writes
 * (firmware_sim/boot_args.hpp: FWSIM_BOOT_ARGS_MAX). */
#define MINRT_FW_BOOT_ARGS_RESERVE 0x1000

/* a3 at entry when firmware-sim passed argc/argv (FWSIM_BOOT_MAGIC). */
#define MINRT_FW_BOOT_MAGIC 0x41524756

/* crt0 fills the stack with this word; the footprint report finds the
 * deepest word that no longer holds it. */
#define MINRT_FW_STACK_PATTERN 0x5ca1ab1e

#endif
