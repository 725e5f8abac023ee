// host-send's raw-protocol receiver on arbitrary bytes from the line: any
// outcome but a crash; a finished image has exactly the pixels it promised.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "ppm_receiver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  using minrt::send::ImageSpec;
  using minrt::send::PpmKind;
  const ImageSpec spec{1 + data[0] % 8, 1 + (data[0] >> 3) % 8, (data[0] & 0x80) ? PpmKind::kP6 : PpmKind::kP3};
  minrt::send::PpmReceiver rx(spec);
  size_t at = 1;
  while (at < size && !rx.done() && !rx.failed() && !rx.firmware_error()) {
    const size_t chunk = 1 + (size - at) % 7;  // uneven pieces, as a line delivers them
    const size_t n = chunk < size - at ? chunk : size - at;
    rx.feed(data + at, n);
    at += n;
  }
  rx.finish();
  if (rx.done() && rx.pixels().size() != static_cast<size_t>(spec.width) * spec.height * 3) std::abort();
  return 0;
}
