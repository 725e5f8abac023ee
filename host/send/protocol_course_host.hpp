// Course protocol, host side (the shared parts are in protocol_course.hpp).
#pragma once

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

// Waits for 0x99, sends the program (4-byte length + bytes), waits for 0xaa,
// sends the scene converted to binary words, then receives the PPM like raw.
TransferResult run_course(Exchange& ex, const std::string& scene_text, const std::string& program,
                          const CourseHostOptions& options, const ImageSpec& spec);

}  // namespace minrt::send
