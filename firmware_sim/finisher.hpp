// SiFive test finisher: the firmware's way to stop the machine with a status.
#pragma once
#include <cstdint>

#include <minrt/memory_map.h>

namespace fwsim {

class Finisher {
 public:
  // Returns true when the write asks the machine to stop.
  bool write(uint32_t value) {
    const uint32_t kind = value & 0xffff;
    if (kind == MINRT_FINISHER_PASS) {
      code_ = 0;
      return true;
    }
    if (kind == MINRT_FINISHER_FAIL) {
      code_ = static_cast<int>(value >> 16);
      return true;
    }
    return false;  // like QEMU, other values (e.g. reset 0x7777) are ignored
  }
  int code() const { return code_; }

 private:
  int code_ = 0;
};

}  // namespace fwsim
