// The firmware's command line (passed by firmware-sim, see
// include/minrt/boot_args.h; empty under QEMU):
//
//   --size WxH         image size, 1..4096 each
//   --format p3|p6     PPM flavour
//   --idle-polls N     empty UART polls that end the input (0: never)
//   --footprint        render, discard the image and print the memory report
//   --protocol=raw|course|framed   serial protocol (default raw), see
//                      docs/host-send.md; framed always renders P6 rows
//   --endian=little|big  byte order of the course protocol's words
//   --ram-size NM      the machine has N MiB of RAM (4..1024; default 4, the
//                      board's): above 4 MiB the render arena moves to the
//                      RAM past the linked image, when that is larger
//   --all-features     CS418: render on the path with every feature compiled
//                      in (to measure what the specialised paths save)
//
// Defaults are build-time settings (MINRT_FW_DEFAULT_* in runtime/CMakeLists.txt).
#pragma once

#include <stdint.h>

#include <minrt/memory_map.h>

#include "core/base/diagnostic.hpp"
#include "render/sld/render.hpp"

#ifndef MINRT_FW_DEFAULT_WIDTH
#define MINRT_FW_DEFAULT_WIDTH 512
#endif
#ifndef MINRT_FW_DEFAULT_HEIGHT
#define MINRT_FW_DEFAULT_HEIGHT 512
#endif
#ifndef MINRT_FW_DEFAULT_P6
#define MINRT_FW_DEFAULT_P6 0
#endif

// What a board does after an image: the board file's after_image, unless
// the build says otherwise (the -small.elf for QEMU halts, so QEMU ends).
#ifndef MINRT_FW_AFTER_IMAGE
#define MINRT_FW_AFTER_IMAGE MINRT_BOARD_AFTER_IMAGE
#endif

namespace minrt::fw {

enum class Protocol { kRaw, kCourse, kFramed };

struct FirmwareOptions {
  RenderOptions render{MINRT_FW_DEFAULT_WIDTH, MINRT_FW_DEFAULT_HEIGHT,
                       MINRT_FW_DEFAULT_P6 ? PpmFormat::kP6 : PpmFormat::kP3};
  uint32_t idle_polls;
  bool footprint = false;
  Protocol protocol = Protocol::kRaw;
  bool big_endian = false;  // course words
  bool all_features = false;  // CS418 path selection off
  uint32_t ram_mib = MINRT_RAM_DEFAULT_SIZE >> 20;  // --ram-size; default: the board's RAM
};

// Fills `options` from argv[1..argc-1]; on a usage error returns false with
// the message in `error`.
bool parse_arguments(int argc, char** argv, FirmwareOptions& options, Diagnostic& error);

}  // namespace minrt::fw
