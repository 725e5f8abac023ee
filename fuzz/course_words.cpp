// The course protocol's two readers against each other: whatever scene the
// host encodes from text, the board's word reader must read back to the
// same values; and arbitrary bytes as words must be read or refused
// cleanly.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "formats/sld/sld_reader.hpp"
#include "protocol/course_word_values.hpp"
#include "protocol_course_host.hpp"

namespace {

namespace course = minrt::send::course;

bool read_words(const std::string& words, minrt::Scene<float>& scene) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(words.data()), words.size()};
  minrt::SldReader<float, course::CourseWordValues<float>> reader(
      course::CourseWordValues<float>(mem.source(), course::Endian::kLittle), minrt::WarningSink{});
  minrt::Diagnostic d;
  return reader.read(scene, d);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string words, error;
  auto scene = std::make_unique<minrt::Scene<float>>();
  if (minrt::send::sld_to_course_words(text, false, words, error)) {
    if (!read_words(words, *scene)) std::abort();  // what the host encodes, the board reads
    minrt::MemorySource mem{data, size};
    minrt::SldReader<float> reader(mem.source(), minrt::WarningSink{});
    auto from_text = std::make_unique<minrt::Scene<float>>();
    minrt::Diagnostic d;
    if (!reader.read(*from_text, d) || from_text->object_count != scene->object_count ||
        from_text->and_count != scene->and_count || from_text->or_count != scene->or_count ||
        std::memcmp(&from_text->beam, &scene->beam, sizeof(float)) != 0)
      std::abort();
  } else if (error.empty()) {
    std::abort();
  }
  read_words(text, *scene);  // the raw bytes as words: no crash
  return 0;
}
