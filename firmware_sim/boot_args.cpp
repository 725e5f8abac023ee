#include "boot_args.hpp"

#include <cstring>
#include <stdexcept>

#include "bus.hpp"
#include "hart_state.hpp"

namespace fwsim {

// The layout does not depend on the length of argv[0] (the ELF path as the
// user spelled it): sp and the argv array sit at the bottom of the fixed-size
// block, and the strings are placed from the top down starting with the last
// argument, so argv[1..] and the stack are at the same addresses however the
// path was written. (sp used to sit just below the strings; a longer path
// moved it down and the firmware's stack-fill loop ran a few iterations
// fewer, so the instruction count changed with the path's spelling.)
void place_boot_args(Bus& bus, HartState& hart, const std::vector<std::string>& args) {
  const uint32_t top = bus.ram_base() + bus.ram_size();
  const uint32_t block = (top - MINRT_BOOT_ARGS_MAX) & ~15u;
  uint32_t need = static_cast<uint32_t>((args.size() + 1) * 4 + 4);
  for (const auto& a : args) need += static_cast<uint32_t>(a.size() + 1);
  if (need > top - block || MINRT_BOOT_ARGS_MAX > bus.ram_size() / 2)
    throw std::runtime_error("firmware arguments too long (limit " +
                             std::to_string(MINRT_BOOT_ARGS_MAX) + " bytes)");
  uint8_t* const ram = bus.ram();
  const uint32_t base = bus.ram_base();
  std::vector<uint32_t> ptrs(args.size());
  uint32_t p = top;
  for (size_t i = args.size(); i-- > 0;) {
    p -= static_cast<uint32_t>(args[i].size() + 1);
    std::memcpy(ram + (p - base), args[i].c_str(), args[i].size() + 1);
    ptrs[i] = p;
  }
  const uint32_t argv = block;
  for (size_t i = 0; i <= ptrs.size(); ++i) {
    const uint32_t v = i < ptrs.size() ? ptrs[i] : 0;
    std::memcpy(ram + (argv + 4 * i - base), &v, 4);
  }
  hart.x[10] = static_cast<uint32_t>(args.size());
  hart.x[11] = argv;
  hart.x[12] = top;
  hart.x[13] = MINRT_BOOT_MAGIC;
  hart.x[2] = block;
}

}  // namespace fwsim
