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

enum class FramedImage { kPpm, kPng, kBmp };
// A CS418 or Jaworski image from its RGBA rows, in the order they came:
// the core's stored-deflate PNG or BMP writer, so the bytes are the ones the
// board streams over raw and course.
std::string framed_rgba_image(FramedImage kind, int width, int height, const std::vector<std::vector<uint8_t>>& rows);

// A text-format scene (`format`: its registry tag): `bytes` as raw would
// send them (texture preamble, text) behind the text-scene header
// (protocol/text_scene_upload.hpp); the board answers with RGBA rows, and
// the result is the `kind` of image (PNG or BMP). `width`/`height`: the
// scene's size, or 0 to take the one the board announces.
TransferResult run_framed_text(Exchange& ex, std::uint32_t format, FramedImage kind, const std::string& bytes,
                               int width, int height,
                               const FramedHostOptions& options = FramedHostOptions{});

}  // namespace minrt::send
