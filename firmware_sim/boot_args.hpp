// Places the boot arguments in simulated memory (the convention is in
// include/minrt/boot_args.h, shared with the firmware).
#pragma once

#include <minrt/boot_args.h>

#ifdef __cplusplus
#include <cstdint>
#include <string>
#include <vector>

namespace fwsim {

class Bus;
struct HartState;

// Writes the block and sets a0..a3 and sp. Throws std::runtime_error when the
// arguments do not fit in MINRT_BOOT_ARGS_MAX bytes.
void place_boot_args(Bus& bus, HartState& hart, const std::vector<std::string>& args);

}  // namespace fwsim
#endif
