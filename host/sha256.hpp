// SHA-256, for checking images against the reference manifests (tests,
// host-send --expect-sha256, benchmarks).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace minrt::host {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  // Lower-case hex digest; the object is finished afterwards.
  std::string hex_digest();

 private:
  void block(const std::uint8_t* p);

  std::uint32_t h_[8];
  std::uint8_t buf_[64];
  std::size_t used_ = 0;
  std::uint64_t total_ = 0;
};

std::string sha256_hex(std::string_view bytes);

}  // namespace minrt::host
