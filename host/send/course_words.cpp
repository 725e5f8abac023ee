// The course protocol's scene words, made by the core's own SLD reader: the
// host reads the text exactly as minrt and the board do (same lexer, number
// rules, checks and messages) and records every value the reader consumes,
// as an int32 or an IEEE single, in the order it consumed them. The board's
// reader asks for the same values in the same order (course_word_values.hpp).
// CS418, Jaworski, miniRT and EASTRAY scenes travel as text behind a header word the SLD
// reader would refuse (protocol/text_scene_upload.hpp).
#include <bit>
#include <cstdint>
#include <memory>

#include "formats/sld/sld_reader.hpp"
#include "protocol/protocol_course.hpp"
#include "protocol/text_scene_upload.hpp"
#include "protocol_course_host.hpp"

namespace minrt::send {
namespace {

// A text value source that also appends each value read as a word.
class RecordingValues {
 public:
  RecordingValues(ByteSource in, course::Endian endian, std::string* words)
      : text_(in), endian_(endian), words_(words) {}

  ValueStatus next_int(int64_t& out) {
    const ValueStatus st = text_.next_int(out);
    // The reader keeps integers saturated to 32 bits, so saturating here
    // changes no decision it makes.
    if (st == ValueStatus::kOk)
      put(static_cast<uint32_t>(out > INT32_MAX ? INT32_MAX : out < INT32_MIN ? INT32_MIN : out));
    return st;
  }
  ValueStatus next_real(float& out) {
    const ValueStatus st = text_.next_real(out);
    if (st == ValueStatus::kOk) put(std::bit_cast<uint32_t>(out));
    return st;
  }
  SourcePos pos() const { return text_.pos(); }
  const char* text() const { return text_.text(); }
  int length() const { return text_.length(); }

 private:
  void put(uint32_t v) {
    uint8_t w[4];
    course::put_u32(w, v, endian_);
    words_->append(reinterpret_cast<const char*>(w), 4);
  }

  SldTextValues<float> text_;
  course::Endian endian_;
  std::string* words_;
};

}  // namespace

bool sld_to_course_words(const std::string& text, bool big_endian, std::string& words, std::string& error) {
  words.clear();
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  const RecordingValues values(mem.source(), big_endian ? course::Endian::kBig : course::Endian::kLittle, &words);
  SldReader<float, RecordingValues> reader(values, WarningSink{});
  auto scene = std::make_unique<Scene<float>>();
  Diagnostic d;
  if (reader.read(*scene, d)) return true;
  // The board's error-line form: "LINE:COL: message".
  error = std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": " + std::string(d.message, d.length);
  return false;
}

std::string text_scene_course_words(std::uint32_t format, const std::string& bytes, bool big_endian) {
  std::string words(text::kHeaderBytes, '\0');
  text::put_header(reinterpret_cast<uint8_t*>(words.data()), format, static_cast<uint32_t>(bytes.size()),
                   big_endian ? course::Endian::kBig : course::Endian::kLittle);
  words += bytes;
  words.resize((words.size() + 3) & ~std::size_t{3}, '\0');  // whole words
  return words;
}

}  // namespace minrt::send
