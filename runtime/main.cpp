// The firmware: reads an SLD scene from the UART, renders it with the
// portable float math and streams the PPM back, row by row. On a bad scene
// or bad arguments it sends one MINRT_ERROR_MARKER line instead and returns
// a non-zero status, which crt0 hands to the test finisher.
#include <minrt/serial_protocol.h>

#include "diagnostic.hpp"
#include "firmware_args.hpp"
#include "footprint.hpp"
#include "math_portable.hpp"
#include "math_rv32f.hpp"
#include "ns16550.hpp"
#include "render.hpp"
#include "serial_stream.hpp"

namespace {

// PortableFloat as the host's `--shims portable`; with MINRT_FW_HW_SQRT the
// square root is fsqrt.s (same bits, see core/math_rv32f.hpp) where the ISA
// has it.
#if MINRT_FW_HW_SQRT
using Math = minrt::PortableFloatHwSqrt;
#else
using Math = minrt::PortableFloat;
#endif

// The scene and the tracer's tables: static, so their size shows in .bss.
minrt::RenderState<Math> g_state;

void send_error(minrt::fw::Ns16550 uart, const minrt::Diagnostic& error) {
  minrt::Diagnostic where;
  if (error.has_pos)
    where.number(error.pos.line).text(":").number(error.pos.col).text(": ");
  uart.write(MINRT_ERROR_MARKER);
  uart.write(where.message);
  uart.write(error.message);
  uart.write("\n");
}

int status_of(minrt::RenderStatus status) {
  switch (status) {
    case minrt::RenderStatus::kOk: return MINRT_STATUS_OK;
    case minrt::RenderStatus::kBadOptions: return MINRT_STATUS_USAGE;
    case minrt::RenderStatus::kSceneError: return MINRT_STATUS_SCENE_ERROR;
    case minrt::RenderStatus::kOutOfMemory: return MINRT_STATUS_OUT_OF_MEMORY;
  }
  return MINRT_STATUS_SCENE_ERROR;
}

}  // namespace

// Called by crt0; extern "C" because freestanding C++ does not treat main
// specially (it would be mangled).
extern "C" int main(int argc, char** argv) {
  minrt::fw::Ns16550 uart = minrt::fw::console_uart();
  uart.init();

  minrt::fw::FirmwareOptions options;
  minrt::Diagnostic error;
  if (!minrt::fw::parse_arguments(argc, argv, options, error)) {
    minrt::Diagnostic usage;
    usage.text("usage: ").text(error.message);
    send_error(uart, usage);
    return MINRT_STATUS_USAGE;
  }

  const minrt::fw::ArenaRegion region = minrt::fw::arena_region();
  minrt::Arena arena(region.base, region.size);
  minrt::fw::SerialInput input(uart, options.idle_polls);
  minrt::fw::SerialOutput output(uart, options.footprint);
  const minrt::RenderStatus status = minrt::render_sld<Math>(
      input.source(), output.sink(), options.render, g_state, arena, error);
  if (status != minrt::RenderStatus::kOk) {
    send_error(uart, error);
    return status_of(status);
  }
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), output.bytes());
  return MINRT_STATUS_OK;
}
