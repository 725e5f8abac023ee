// The board's side of the session (protocol/session.hpp): waiting for a
// host, the identity line, the run's options. main.cpp runs the protocols.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "firmware_args.hpp"
#include "uart.hpp"

namespace minrt::fw {

// What the wait for a host found.
enum class HostEvent {
  kScene,      // the first byte of a raw, framed or course exchange (put back)
  kOptions,    // an options line, accepted: `options` holds the run's
  kWaitedOut,  // `wait_polls` empty polls (0: never)
};

struct BoardFacts {
  uint32_t ram_bytes = 0;
  uint32_t arena_bytes = 0;
};

// Waits for the host: greetings are answered (the identity line), options
// lines accepted or refused (an error line), line noise skipped when
// `skip_noise` (a board waiting between scenes: bytes that start no
// exchange, such as the 0x00 and 0xFF of a line that settles). `options`
// starts as the board's defaults and, on kOptions, holds the run's.
HostEvent wait_for_host(Uart uart, uint32_t wait_polls, bool skip_noise, const BoardFacts& facts,
                        FirmwareOptions& options);

}  // namespace minrt::fw
