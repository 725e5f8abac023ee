// Runs a few encoded instructions on a fresh Machine: registers are set
// directly, the program ends with ebreak.
#pragma once
#include <bit>
#include <cstdint>
#include <cstring>
#include <vector>

#include "machine.hpp"
#include "rv_encoder.hpp"

struct Sim {
  fwsim::Machine m{1u << 20};

  explicit Sim(std::vector<uint32_t> code) {
    code.push_back(rv::ebreak());
    std::memcpy(m.bus().ram(), code.data(), code.size() * 4);
    m.hart().pc = fwsim::kRamBase;
  }
  uint32_t& x(unsigned i) { return m.hart().x[i]; }
  uint32_t& f(unsigned i) { return m.hart().f[i]; }
  // Runs to the final ebreak; anything else stopping the run is returned too.
  fwsim::StopInfo run(uint64_t limit = 1'000'000) { return m.run(limit); }
};

inline uint32_t bits_of(float v) { return std::bit_cast<uint32_t>(v); }
