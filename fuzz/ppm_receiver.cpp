// host-send's raw-protocol receiver on arbitrary bytes from the line: any
// outcome but a crash; a finished image has exactly the pixels it promised.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "checked_reply.hpp"
#include "ppm_receiver.hpp"

namespace {

// Feeds the line's bytes in uneven pieces, as a line delivers them.
template <class Receiver>
void feed_all(Receiver& rx, const uint8_t* data, size_t size) {
  size_t at = 1;
  while (at < size && !rx.done() && !rx.failed() && !rx.firmware_error()) {
    const size_t chunk = 1 + (size - at) % 7;
    const size_t n = chunk < size - at ? chunk : size - at;
    rx.feed(data + at, n);
    at += n;
  }
  rx.finish();
}

}  // namespace

// First byte: width (bits 0-2), height (bits 3-5), through the CRC-32
// trailer's CheckedReply (bit 6), P6 (bit 7).
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  using minrt::send::ImageSpec;
  using minrt::send::PpmKind;
  const ImageSpec spec{1 + data[0] % 8, 1 + (data[0] >> 3) % 8, (data[0] & 0x80) ? PpmKind::kP6 : PpmKind::kP3};
  minrt::send::PpmReceiver rx(spec);
  if (data[0] & 0x40) {
    minrt::send::CheckedReply<minrt::send::PpmReceiver> checked(rx, minrt::send::RawCheck::kAuto);
    feed_all(checked, data, size);
    // A checked image matched its trailer: its bytes are the CRC's.
    if (checked.done() && checked.checked() && !rx.done()) std::abort();
    if (checked.done() && rx.pixels().size() != static_cast<size_t>(spec.width) * spec.height * 3) std::abort();
    return 0;
  }
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
