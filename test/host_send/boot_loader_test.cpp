// The firmware's course boot stage: an uploaded program is loaded at
// MINRT_PROGRAM_LOAD_ADDR and run. The renderer uploaded as a program
// (minrt-rv32imf-program.bin) must give the built-in renderer's and the
// host's bytes; the probe program (minrt-rv32imf-probe.bin) shows that the
// uploaded code itself runs; oversized and cut-short uploads are refused.
#include <catch2/catch.hpp>

#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "protocol/protocol_course.hpp"
#include "test_support.hpp"

namespace {

std::string scene(const std::string& name) { return hs_test::shared_dir() + "/scenes/" + name; }

// The length word (claiming `length` bytes) and the program bytes.
std::string upload(const std::string& program, bool big_endian, uint32_t length) {
  std::string out(4, '\0');
  minrt::send::course::put_u32(reinterpret_cast<uint8_t*>(out.data()), length,
                               big_endian ? minrt::send::course::Endian::kBig : minrt::send::course::Endian::kLittle);
  return out + program;
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// firmware-sim running the resident firmware in course mode with `input`
// on its UART; the UART output in `out`.
hs_test::RunResult run_course_firmware(const hs_test::TempDir& dir, const std::string& input, bool big_endian,
                                       std::string& out) {
  write_file(dir.file("uart-in"), input);
  const auto r = hs_test::run({HS_FIRMWARE_SIM, "--uart-in", dir.file("uart-in"), "--uart-out", dir.file("uart-out"),
                               HS_FIRMWARE_ELF, "--", "--protocol=course",
                               big_endian ? "--endian=big" : "--endian=little"});
  out = hs_test::read_file(dir.file("uart-out"));
  return r;
}

const std::string kProgramRequest(1, '\x99');

}  // namespace

TEST_CASE("the firmware runs the uploaded renderer like its built-in one", "[boot][course][firmware]") {
  HS_NEEDS_FIRMWARE();
  REQUIRE(hs_test::file_exists(HS_PROGRAM_BIN));
  hs_test::TempDir dir;
  struct Case {
    const char *scene, *size, *format, *endian;
  };
  for (const Case& c : {Case{"contest.sld", "32x32", "p6", "little"}, Case{"tron.sld", "24x16", "p3", "big"},
                        Case{"ball.sld", "32x24", "p6", "big"}}) {
    const std::string ref = hs_test::reference_image(scene(c.scene), c.size, c.format);
    REQUIRE_FALSE(ref.empty());
    for (const bool uploaded : {true, false}) {
      const std::string out = dir.file(std::string(c.scene) + (uploaded ? ".program.ppm" : ".builtin.ppm"));
      std::vector<std::string> argv{HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                                    "--protocol", "course", "--endian", c.endian, "--size", c.size,
                                    "--format", c.format, scene(c.scene), "-o", out};
      if (uploaded) argv.insert(argv.end(), {"--program", HS_PROGRAM_BIN});
      const auto r = hs_test::run(argv);
      INFO(c.scene << " " << c.size << " " << c.format << " " << c.endian << (uploaded ? " uploaded" : " built-in")
                   << "\n" << r.err);
      REQUIRE(r.status == 0);
      CHECK(hs_test::read_file(out) == ref);
    }
  }
}

TEST_CASE("an uploaded program runs from the program region with the boot loader's handoff", "[boot][firmware]") {
  HS_NEEDS_FIRMWARE();
  const std::string probe = hs_test::read_file(HS_PROBE_BIN);
  REQUIRE(!probe.empty());
  hs_test::TempDir dir;
  for (const bool big : {false, true}) {
    std::string out;
    const auto r = run_course_firmware(dir, upload(probe, big, static_cast<uint32_t>(probe.size())), big, out);
    INFO((big ? "big" : "little") << "\n" << r.err);
    CHECK(r.status == 42);  // the probe's status, not the renderer's
    REQUIRE(out.size() > 1);
    CHECK_THAT(out, Catch::StartsWith(kProgramRequest + "boot probe: pc 0x801"));
    CHECK_THAT(out, Catch::EndsWith(std::string(" (in the program region), started by the boot loader, ") +
                                    (big ? "big" : "little") + "-endian words, argc 3, last argument --endian=" +
                                    (big ? "big" : "little") + "\n"));
  }
  // Exactly MINRT_PROGRAM_MAX_SIZE bytes still fit: the probe padded with zeros.
  std::string padded = probe;
  padded.resize(MINRT_PROGRAM_MAX_SIZE, '\0');
  std::string out;
  const auto r = run_course_firmware(dir, upload(padded, false, MINRT_PROGRAM_MAX_SIZE), false, out);
  CHECK(r.status == 42);
  CHECK_THAT(out, Catch::Contains("started by the boot loader"));
}

TEST_CASE("a program larger than the program region is refused", "[boot][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const uint32_t too_big = MINRT_PROGRAM_MAX_SIZE + 1;
  const std::string message = "course: program of " + std::to_string(too_big) + " bytes does not fit the board's " +
                              std::to_string(MINRT_PROGRAM_MAX_SIZE) + "-byte program region";
  // The board answers right after the length word.
  std::string out;
  const auto direct = run_course_firmware(dir, upload("", false, too_big), false, out);
  CHECK(direct.status == MINRT_STATUS_BAD_PROGRAM);
  CHECK(out == kProgramRequest + MINRT_ERROR_MARKER + message + "\n");
  // host-send refuses such a file itself, before the link is opened
  // (general:host-send refuses a --program larger than the board's program
  // region ..., test/host/scene_size_test.cpp).
}

TEST_CASE("a cut-short program upload gives the error line", "[boot][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  const std::string probe = hs_test::read_file(HS_PROBE_BIN);
  REQUIRE(probe.size() > 100);
  hs_test::TempDir dir;
  // The firmware takes the silence after 100 bytes as the end of the upload.
  std::string out;
  auto r = run_course_firmware(dir, upload(probe.substr(0, 100), false, static_cast<uint32_t>(probe.size())), false,
                               out);
  CHECK(r.status == MINRT_STATUS_BAD_PROGRAM);
  CHECK(out == kProgramRequest + MINRT_ERROR_MARKER + "course: program ended early, " +
                   std::to_string(probe.size() - 100) + " of " + std::to_string(probe.size()) + " bytes missing\n");
  // Not even the length word.
  r = run_course_firmware(dir, std::string("\x10\x00", 2), false, out);
  CHECK(r.status == MINRT_STATUS_BAD_PROGRAM);
  CHECK(out == kProgramRequest + MINRT_ERROR_MARKER + "course: no program size from the host\n");
}
