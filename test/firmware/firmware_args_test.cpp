// The firmware's argument parser (runtime/firmware_args.cpp), built for the host.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "firmware_args.hpp"

namespace {

struct Parsed {
  bool ok;
  minrt::fw::FirmwareOptions options;
  std::string error;
};

Parsed parse(std::vector<std::string> args) {
  args.insert(args.begin(), "minrt-rv32imf.elf");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  Parsed p{};
  minrt::Diagnostic error;
  p.ok = minrt::fw::parse_arguments(static_cast<int>(args.size()), argv.data(), p.options, error);
  p.error = error.message;
  return p;
}

}  // namespace

TEST_CASE("firmware arguments: defaults come from the build", "[firmware]") {
  const Parsed p = parse({});
  REQUIRE(p.ok);
  CHECK(p.options.render.width == MINRT_FW_DEFAULT_WIDTH);
  CHECK(p.options.render.height == MINRT_FW_DEFAULT_HEIGHT);
  CHECK(p.options.render.format == minrt::PpmFormat::kP3);
  CHECK(p.options.idle_polls == MINRT_IDLE_POLLS_DEFAULT);
  CHECK_FALSE(p.options.footprint);
}

TEST_CASE("firmware arguments: no argv at all (QEMU) keeps the defaults", "[firmware]") {
  minrt::fw::FirmwareOptions options;
  minrt::Diagnostic error;
  REQUIRE(minrt::fw::parse_arguments(0, nullptr, options, error));
  CHECK(options.render.width == MINRT_FW_DEFAULT_WIDTH);
}

TEST_CASE("firmware arguments: size, format, idle polls, footprint", "[firmware]") {
  const Parsed p = parse({"--size", "128x96", "--format", "p6", "--idle-polls", "0", "--footprint"});
  REQUIRE(p.ok);
  CHECK(p.options.render.width == 128);
  CHECK(p.options.render.height == 96);
  CHECK(p.options.render.format == minrt::PpmFormat::kP6);
  CHECK(p.options.idle_polls == 0);
  CHECK(p.options.footprint);
  CHECK(parse({"--size", "4096x4096"}).ok);
  CHECK(parse({"--format", "P3"}).ok);
}

TEST_CASE("firmware arguments: usage errors name the problem", "[firmware]") {
  struct Case {
    std::vector<std::string> args;
    const char* message;
  };
  const Case cases[] = {
      {{"--size"}, "--size needs a value"},
      {{"--size", "0x10"}, "bad --size '0x10': expected WxH, each 1..4096"},
      {{"--size", "4097x1"}, "bad --size '4097x1': expected WxH, each 1..4096"},
      {{"--size", "12"}, "bad --size '12': expected WxH, each 1..4096"},
      {{"--size", "x12"}, "bad --size 'x12': expected WxH, each 1..4096"},
      {{"--size", "12x"}, "bad --size '12x': expected WxH, each 1..4096"},
      {{"--size", "99999999999x1"}, "bad --size '99999999999x1': expected WxH, each 1..4096"},
      {{"--format", "png"}, "bad --format 'png': expected p3 or p6"},
      {{"--idle-polls", "-1"}, "bad --idle-polls '-1': expected a count of polls (0: wait forever)"},
      {{"--idle-polls", "4294967296"},
       "bad --idle-polls '4294967296': expected a count of polls (0: wait forever)"},
      {{"scene.sld"}, "unknown argument 'scene.sld'"},
  };
  for (const Case& c : cases) {
    INFO(c.args.back());
    const Parsed p = parse(c.args);
    CHECK_FALSE(p.ok);
    CHECK(p.error == c.message);
  }
}
