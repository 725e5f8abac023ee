// The FPU-model options end to end: --fpu / --fpu-model on the test firmware
// and on the renderer firmware, their errors, and --fpu-check's verdicts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
// Tables of 3 bits and no Newton step: errors of a few percent.
const std::string kCoarse =
    "div=recip-mul,recip_table_bits=3,recip_newton_steps=0,sqrt=table-newton,rsqrt_table_bits=3,"
    "rsqrt_newton_steps=0";

// The test firmware's output line starting with `key`.
std::string line_of(const std::string& out, const std::string& key) {
  const size_t at = out.find("\n" + key + " ");
  if (at == std::string::npos) return "";
  return out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}
}  // namespace

TEST_CASE("an FPU model changes float results and leaves integer ones", "[cli][fpu]") {
  const Result ieee = sim(kElf), coarse = sim("--fpu " + kCoarse + " " + kElf);
  REQUIRE(ieee.status == 0);
  REQUIRE(coarse.status == 0);
  CHECK(line_of(coarse.out, "hash") == line_of(ieee.out, "hash"));
  CHECK(line_of(coarse.out, "div") == line_of(ieee.out, "div"));
  CHECK(line_of(coarse.out, "recur") == line_of(ieee.out, "recur"));
  CHECK(line_of(coarse.out, "dot") != line_of(ieee.out, "dot"));  // 1/(i+1) by fdiv.s
  CHECK(line_of(coarse.out, "sqrt") != line_of(ieee.out, "sqrt"));
  CHECK(line_of(coarse.out, "special") == line_of(ieee.out, "special"));  // 1/0, 0/0 stay IEEE
}

TEST_CASE("a model file equals the same --fpu items and --fpu overrides it", "[cli][fpu]") {
  const std::string cfg = temp_path("team.cfg");
  spit(cfg, "# coarse unit\ndiv = recip-mul\nrecip_table_bits = 3\nrecip_newton_steps = 0\n"
            "sqrt = table-newton\nrsqrt_table_bits = 3\nrsqrt_newton_steps = 0\n");
  const Result file = sim("--fpu-model " + cfg + " " + kElf);
  const Result items = sim("--fpu " + kCoarse + " " + kElf);
  CHECK(file.status == 0);
  CHECK(file.out == items.out);
  const Result back = sim("--fpu-model " + cfg + " --fpu div=exact,sqrt=exact " + kElf);
  CHECK(back.out == sim(kElf).out);
  std::remove(cfg.c_str());
}

TEST_CASE("stats name the FPU model", "[cli][fpu]") {
  CHECK(sim("--stats " + kElf).err.find("\nfpu model: ieee") != std::string::npos);
  // The documented template lists every key at its IEEE default.
  const Result t = sim("--stats --fpu-model " + std::string(FWSIM_SOURCE_DIR) + "/firmware_sim/models/fpu-ieee.cfg " + kElf);
  CHECK(t.status == 0);
  CHECK(t.err.find("\nfpu model: ieee") != std::string::npos);
  const Result r = sim("--stats --fpu div=recip-mul,recip_table_bits=9 " + kElf);
  CHECK(r.err.find("\nfpu model: div=recip-mul(table 9 bits, entries 23 bits, 1 Newton step) sqrt=exact") !=
        std::string::npos);
}

TEST_CASE("bad FPU options are a one-line error with status 2", "[cli][fpu][usage]") {
  auto one_line = [](const Result& r) {
    CHECK(r.status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  };
  Result r = sim("--fpu recip_table_bits=40 " + kElf);
  one_line(r);
  CHECK(r.err == "firmware-sim: error: --fpu 'recip_table_bits=40': recip_table_bits must be an integer from 0 "
                 "to 16, got '40'\n");
  r = sim("--fpu div=slow " + kElf);
  one_line(r);
  CHECK(r.err.find("unknown div 'slow'") != std::string::npos);
  one_line(sim(kElf + " --fpu"));
  r = sim("--fpu-model /nonexistent/team.cfg " + kElf);
  one_line(r);
  CHECK(r.err == "firmware-sim: error: /nonexistent/team.cfg: cannot read FPU model: No such file or directory\n");
  const std::string cfg = temp_path("bad.cfg");
  spit(cfg, "div = recip-mul\nsqrt = cordic\n");
  r = sim("--fpu-model " + cfg + " " + kElf);
  one_line(r);
  CHECK(r.err == "firmware-sim: error: " + cfg + ":2: unknown sqrt 'cordic' (exact, table-newton)\n");
  std::remove(cfg.c_str());
  r = sim("--fpu-check " + kElf);
  one_line(r);
  CHECK(r.err.find("--fpu-check runs no firmware") != std::string::npos);
}

TEST_CASE("fpu-check passes a rule-meeting model and fails a coarse one", "[cli][fpu][check]") {
  const Result good = sim("--fpu div=recip-mul,recip_table_bits=10,recip_newton_steps=1 --fpu-check");
  CHECK(good.status == 0);
  CHECK(good.out.find("fpu model: div=recip-mul(table 10 bits") == 0);
  CHECK(good.out.find("all ops meet the course's rules") != std::string::npos);
  const Result bad = sim("--fpu div=recip-mul,recip_table_bits=8,recip_newton_steps=1 --fpu-check");
  CHECK(bad.status == 1);
  const std::string fdiv = line_of("\n" + bad.out, "fdiv");
  CHECK(fdiv.find("MISS") != std::string::npos);
  CHECK(line_of("\n" + bad.out, "fsqrt").find("meet") != std::string::npos);
  CHECK(bad.out.find("worst fdiv: fdiv(0x") != std::string::npos);
}

#ifdef FWSIM_RENDERER_ELF
namespace {
// Renders the scene at 32x32 (P6) under `fpu` options; returns the image bytes.
std::string render(const std::string& fpu) {
  const std::string out = temp_path("render.ppm");
  const Result r = sim(fpu + " --uart-in " + FWSIM_RENDER_SCENE + " --uart-out " + out + " " + FWSIM_RENDERER_ELF +
                       " -- --size 32x32 --format p6");
  CHECK(r.status == 0);
  std::string image = slurp(out);
  std::remove(out.c_str());
  return image;
}

// Pixels whose colour differs, between two complete 32x32 P6 images.
int differing_pixels(const std::string& a, const std::string& b) {
  const size_t header = std::string("P6\n32 32 255\n").size();
  int n = 0;
  for (size_t p = header; p + 3 <= a.size(); p += 3)
    if (a.compare(p, 3, b, p, 3) != 0) ++n;
  return n;
}
}  // namespace

TEST_CASE("the renderer firmware under FPU models gives complete images that differ by model", "[cli][fpu]") {
  const std::string header = "P6\n32 32 255\n";
  const std::string ieee = render("");
  const std::string meeting = render("--fpu div=recip-mul,sqrt=table-newton");
  const std::string coarse = render("--fpu " + kCoarse);
  for (const std::string* image : {&ieee, &meeting, &coarse}) {
    REQUIRE(image->size() == header.size() + 32 * 32 * 3);
    CHECK(image->compare(0, header.size(), header) == 0);
  }
  const int near = differing_pixels(ieee, meeting), far = differing_pixels(ieee, coarse);
  CAPTURE(near, far);
  CHECK(far > 32 * 32 / 2);    // a few percent of error in every division moves most pixels
  CHECK(near < 32 * 32 / 20);  // the rule-meeting unit moves only a few
  CHECK(near < far);
}
#endif
