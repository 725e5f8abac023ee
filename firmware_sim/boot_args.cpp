#include "boot_args.hpp"

#include <cstring>
#include <stdexcept>

#include "bus.hpp"
#include "hart_state.hpp"

namespace fwsim {

void place_boot_args(Bus& bus, HartState& hart, const std::vector<std::string>& args) {
  const uint32_t top = kRamBase + bus.ram_size();
  uint32_t need = static_cast<uint32_t>((args.size() + 1) * 4 + 16 + 4);
  for (const auto& a : args) need += static_cast<uint32_t>(a.size() + 1);
  if (need > MINRT_BOOT_ARGS_MAX || need > bus.ram_size() / 2)
    throw std::runtime_error("firmware arguments too long (limit " +
                             std::to_string(MINRT_BOOT_ARGS_MAX) + " bytes)");
  uint32_t p = top;
  std::vector<uint32_t> ptrs;
  for (const auto& a : args) {
    p -= static_cast<uint32_t>(a.size() + 1);
    std::memcpy(bus.ram() + (p - kRamBase), a.c_str(), a.size() + 1);
    ptrs.push_back(p);
  }
  p &= ~3u;
  p -= static_cast<uint32_t>((ptrs.size() + 1) * 4);
  const uint32_t argv = p;
  for (size_t i = 0; i <= ptrs.size(); ++i) {
    uint32_t v = i < ptrs.size() ? ptrs[i] : 0;
    std::memcpy(bus.ram() + (argv + 4 * i - kRamBase), &v, 4);
  }
  hart.x[10] = static_cast<uint32_t>(args.size());
  hart.x[11] = argv;
  hart.x[12] = top;
  hart.x[13] = MINRT_BOOT_MAGIC;
  hart.x[2] = argv & ~15u;
}

}  // namespace fwsim
