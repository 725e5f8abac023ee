// Course protocol, host side (the shared parts are in protocol_course.hpp).
#pragma once

#include <cstdint>
#include <string>

#include "protocol_raw.hpp"

namespace minrt::send {

struct CourseHostOptions {
  bool big_endian = false;
  int handshake_timeout_ms = 30000;
};

// The scene as course words, read by the core's SLD reader in single
// precision (course_words.cpp); false with the reader's located message
// ("LINE:COL: message", as the board reports it) for a scene it refuses.
bool sld_to_course_words(const std::string& text, bool big_endian, std::string& words, std::string& error);

// A CS418 or Jaworski scene (the bytes raw would send: texture preamble
// and text) as course words: the text-scene header, the bytes, zero padding
// to a whole word (protocol/text_scene_upload.hpp).
std::string text_scene_course_words(std::uint32_t format, const std::string& bytes, bool big_endian);

// Waits for 0x99, sends the program (4-byte length + bytes), waits for 0xaa,
// sends the scene converted to binary words, then receives the PPM like raw.
TransferResult run_course(Exchange& ex, const std::string& scene_text, const std::string& program,
                          const CourseHostOptions& options, const ImageSpec& spec);

// The same conversation for words made by text_scene_course_words: the
// reply is the format's image, checked by `rx` (PngReceiver for CS418,
// BmpReceiver for Jaworski) as in the raw protocol.
template <class Receiver>
TransferResult run_course_words(Exchange& ex, const std::string& words, const std::string& program,
                                const CourseHostOptions& options, Receiver& rx);

}  // namespace minrt::send
