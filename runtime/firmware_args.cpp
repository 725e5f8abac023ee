#include "firmware_args.hpp"

#include <minrt/limits.hpp>
#include <minrt/serial_protocol.h>

#include "core/base/text_numbers.hpp"
#include "same_text.hpp"

namespace minrt::fw {
namespace {

int length(const char* s) {
  int n = 0;
  while (s[n] != 0) ++n;
  return n;
}

Diagnostic& bad_value(Diagnostic& error, const char* option, const char* value) {
  return error.text("bad ").text(option).text(" ").quoted(value, length(value)).text(": expected ");
}

}  // namespace

// A port whose UART receives slower than the firmware polls (QEMU's
// one-byte CMSDK UART) builds with 0: wait for the scene's own end.
#ifndef MINRT_FW_DEFAULT_IDLE_POLLS
#define MINRT_FW_DEFAULT_IDLE_POLLS MINRT_IDLE_POLLS_DEFAULT
#endif

bool parse_arguments(int argc, char** argv, FirmwareOptions& options, Diagnostic& error) {
  options.idle_polls = MINRT_FW_DEFAULT_IDLE_POLLS;
  for (int i = 1; i < argc; ++i) {
    const char* arg = argv[i];
    const bool takes_value =
        same_text(arg, "--size") || same_text(arg, "--format") || same_text(arg, "--idle-polls") || same_text(arg, "--ram-size");
    if (takes_value && i + 1 >= argc) {
      error.text(arg).text(" needs a value");
      return false;
    }
    if (same_text(arg, "--size")) {
      const char* v = argv[++i];
      if (!parse_size(v, options.render.width, options.render.height)) {
        bad_value(error, arg, v).text("WxH, each 1..").number(limits::kMaxImageWidth);
        return false;
      }
    } else if (same_text(arg, "--format")) {
      const char* v = argv[++i];
      if (same_text(v, "p3") || same_text(v, "P3")) {
        options.render.format = PpmFormat::kP3;
      } else if (same_text(v, "p6") || same_text(v, "P6")) {
        options.render.format = PpmFormat::kP6;
      } else {
        bad_value(error, arg, v).text("p3 or p6");
        return false;
      }
    } else if (same_text(arg, "--idle-polls")) {
      const char* v = argv[++i];
      if (!parse_decimal(v, 0, 0xffffffffu, options.idle_polls)) {
        bad_value(error, arg, argv[i]).text("a count of polls (0: wait forever)");
        return false;
      }
    } else if (same_text(arg, "--protocol=raw")) {
      options.protocol = Protocol::kRaw;
    } else if (same_text(arg, "--protocol=course")) {
      options.protocol = Protocol::kCourse;
    } else if (same_text(arg, "--protocol=framed")) {
      options.protocol = Protocol::kFramed;
    } else if (same_text(arg, "--endian=little")) {
      options.big_endian = false;
    } else if (same_text(arg, "--endian=big")) {
      options.big_endian = true;
    } else if (same_text(arg, "--ram-size")) {
      const char* v = argv[++i];
      const char* p = v;
      if (!parse_decimal(p, 'M', 1024, options.ram_mib) || *p != 'M' || p[1] != 0 || options.ram_mib < 4) {
        bad_value(error, arg, v).text("NM, 4M..1024M");
        return false;
      }
    } else if (same_text(arg, "--all-features")) {
      options.all_features = true;
    } else if (same_text(arg, "--footprint")) {
      options.footprint = true;
    } else {
      error.text("unknown argument ").quoted(arg, length(arg));
      return false;
    }
  }
  return true;
}

}  // namespace minrt::fw
