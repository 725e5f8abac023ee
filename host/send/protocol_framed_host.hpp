// Framed protocol, host side (the shared parts are in protocol_framed.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "protocol_raw.hpp"

namespace minrt::send {

struct FramedHostOptions {
  int ack_timeout_ms = 3000;  // no K after the upload: upload again
  int retry_ms = 1500;        // silence after which missing rows are requested
  int max_uploads = 8;
};

// The S...E frames that carry `scene`.
std::string framed_upload(const std::string& scene);
// The PPM (P3 or P6 as `spec` says) from RGB rows, byte for byte what the
// renderer writes.
std::string framed_image(const ImageSpec& spec, const std::vector<std::vector<uint8_t>>& rows);

TransferResult run_framed(Exchange& ex, const std::string& scene_text, const ImageSpec& spec,
                          const FramedHostOptions& options = FramedHostOptions{});

}  // namespace minrt::send
