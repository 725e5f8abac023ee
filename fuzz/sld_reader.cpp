// The SLD reader on arbitrary bytes, in both precisions: it must accept or
// refuse with a located message, never crash or read out of bounds; a scene
// it accepts must have every network entry in range (what the tracer
// indexes with).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "formats/sld/sld_reader.hpp"

namespace {

template <class R>
void read_one(const uint8_t* data, size_t size) {
  minrt::MemorySource mem{data, size};
  minrt::SldReader<R> reader(mem.source(), minrt::WarningSink{});
  auto scene = std::make_unique<minrt::Scene<R>>();
  minrt::Diagnostic d;
  if (!reader.read(*scene, d)) {
    if (d.length <= 0 || !d.has_pos) std::abort();  // a refusal always says what and where
    return;
  }
  for (int n = 0; n < scene->and_count; ++n)
    for (int k = 0; scene->and_nets[n][k] != -1; ++k)
      if (scene->and_nets[n][k] < 0 || scene->and_nets[n][k] >= scene->object_count) std::abort();
  for (int r = 0; r < scene->or_count; ++r)
    for (int k = 1; scene->or_nets[r][k] != -1; ++k)
      if (scene->or_nets[r][k] < 0 || scene->or_nets[r][k] >= scene->and_count) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  read_one<double>(data, size);
  read_one<float>(data, size);
  return 0;
}
