/* Boot-argument convention between firmware-sim and the firmware's crt0,
 * defined once for both (C, C++ and assembly/linker-script preprocessing).
 *
 * At entry (pc = ELF entry point) the simulator has written, at the top of RAM:
 *
 *   RAM end ->  +--------------------------------------+
 *               | argument strings, NUL-terminated,    |
 *               | argv[argc-1] highest, argv[0] lowest |
 *               | free                                 |
 *               | argv[argc] = 0                       |
 *               | argv[0] ... argv[argc-1] (pointers)  |
 *   RAM end - MINRT_BOOT_ARGS_MAX ---------+  <- a1 = argv = sp
 *
 * The layout does not depend on the length of argv[0] (the ELF path as the
 * user spelled it): sp, argv and argv[1..] are at the same addresses however
 * the path is written, so instruction counts do not change with it.
 *
 * The registers:
 *   a0 = argc          (argv[0] is the ELF path given on the command line,
 *                       argv[1..] are the ARGS after "--")
 *   a1 = argv
 *   a2 = RAM end       (RAM base + RAM size; useful for a heap limit)
 *   a3 = MINRT_BOOT_MAGIC, which says a0..a2 are valid
 *   sp = RAM end - MINRT_BOOT_ARGS_MAX (16-byte aligned; the stack grows
 *        down from there, below the block)
 * All other registers, fcsr and the counters are 0.
 *
 * crt0 rule: if a3 == MINRT_BOOT_MAGIC keep sp as given (the block lies above
 * it) and pass a0/a1 to main; otherwise (e.g. QEMU -M virt, which puts the hart
 * id in a0 and a device tree pointer in a1) set sp from the linker script and
 * call main(0, NULL). The whole block takes at most MINRT_BOOT_ARGS_MAX bytes,
 * so a linker script that keeps the stack top MINRT_BOOT_ARGS_MAX below RAM end
 * is safe either way.
 */
#pragma once

#define MINRT_BOOT_MAGIC 0x41524756 /* "VGRA": bytes 'V','G','R','A' read as LE word */
#define MINRT_BOOT_ARGS_MAX 4096
