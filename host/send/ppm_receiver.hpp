// Incremental check of the firmware's reply: either a PPM image of the
// expected size and format, or one MINRT_ERROR_MARKER line. Bytes are fed as
// they arrive; the receiver stops consuming at the end of the image so the
// caller can write exactly the image bytes (OutputFile) and hash them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "reply_receiver.hpp"
#include "posix/output_file.hpp"
#include <vector>

namespace minrt::send {

enum class PpmKind { kP3, kP6 };

struct ImageSpec {
  int width = 512;
  int height = 512;
  PpmKind kind = PpmKind::kP6;
};

// Bytes of a P6 image of `spec` including the header "P6\nW H 255\n" as the
// renderer writes it; for P3 an estimate (values average ~2.5 digits).
std::uint64_t expected_image_bytes(const ImageSpec& spec);
std::string ppm_header(const ImageSpec& spec);

// kBody: the pixel data.
class PpmReceiver : public ReplyReceiver {
 public:
  explicit PpmReceiver(const ImageSpec& expected);

  // Consumes bytes up to the end of the image (or of the error line) and
  // returns how many it took; after kDone/kFailed/kFirmwareError it takes none.
  std::size_t feed(const std::uint8_t* data, std::size_t size);
  // The line went quiet or closed: a P3 image missing only its final
  // newline counts as complete; anything else is truncated.
  void finish();

  int rows_complete() const;
  // Decoded pixels, RGB, row-major (complete once done()).
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }
  const ImageSpec& expected() const { return expected_; }

 private:
  bool step(std::uint8_t c);
  bool fail_p3(const char* what);  // damaged P3 pixel data, located
  bool header_token_done();

  ImageSpec expected_;
  // Header parsing.
  int header_field_ = 0;  // 0 magic, 1 width, 2 height, 3 maxval
  std::string token_;
  bool in_comment_ = false;
  PpmKind kind_ = PpmKind::kP6;
  long values_[4] = {0, 0, 0, 0};
  // Payload.
  std::vector<std::uint8_t> pixels_;
  std::size_t pixel_bytes_ = 0;  // channel values stored so far
  int p3_value_ = -1;            // digits of the current P3 value, -1 if none
  int p3_digits_ = 0;
};

}  // namespace minrt::send

namespace minrt::send {

// Writes `bytes` to a temporary file next to `path` and renames it into
// place, so `path` is either the complete image or untouched. "-" writes to
// standard output (posix/output_file.hpp).
using minrt::host::write_file_atomically;

}  // namespace minrt::send
