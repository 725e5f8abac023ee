// shim-ulp-table: prints a Markdown table of the accuracy of each math policy
// (C library float, portable minimum, fast and accurate) over the named ranges
// of tools/shim_ulp/ulp_stats.hpp, plus the int <-> float conversion checks.
//
//   shim-ulp-table [--refine N] [--exhaustive] [--only sqrt|floor|sin|cos|atan|conv]
//                  [--no-libm] [--renderer] [--level 0|1|2]
//
// --renderer keeps only the ranges the renderer uses (named "renderer ...").
// --refine N divides the sampling strides (default 16); --exhaustive visits
// every float of every range (minutes per function); --level keeps one
// portable level (and drops the libm rows).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "posix/command_line.hpp"
#include "ulp_stats.hpp"

namespace {

using namespace shim_ulp;

const minrt::cli::Tool& tool() {
  static const minrt::cli::Tool t{
      "shim-ulp-table",
      R"(Usage: shim-ulp-table [OPTIONS]
Prints a Markdown table of the accuracy of each math policy (C library float,
portable minimum, fast and accurate) over the ranges the renderer uses, and the
int <-> float conversion checks (docs/shims.md).

)",
      {
          {"refine", 0, "N", "divide the sampling strides by N (default 16)"},
          {"exhaustive", 0, nullptr, "visit every float of every range (minutes per function)"},
          {"only", 0, "FN", "one function: sqrt, floor, sin, cos, atan, or conv"},
          {"no-libm", 0, nullptr, "leave out the C library rows"},
          {"renderer", 0, nullptr, "keep only the ranges the renderer uses"},
          {"level", 0, "0|1|2", "keep one portable level (and drop the libm rows)"},
      },
      ""};  // no operands
  return t;
}

std::string log2_text(double v) {
  if (v == 0.0) return "0";
  if (!std::isfinite(v)) return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "2^%.1f", std::log2(v));
  return buf;
}

template <class P>
void table_rows(Fn f, std::int64_t refine, bool renderer_only) {
  for (const Range& r : ranges_for(f, refine)) {
    if (renderer_only && r.name.rfind("renderer", 0) != 0) continue;
    const Stats s = measure<P>(f, r);
    const int rule = course_rule_log2(f);
    const bool ok = rule == 0 ? s.max_ulp == 0.0
                              : s.max_rel < std::ldexp(1.0, rule);
    char worst[32] = "-";  // no worst case when every result is exact
    if (s.max_ulp > 0.0) std::snprintf(worst, sizeof worst, "%.9g", double(s.worst_arg));
    std::printf("| %s | %s | %s | %llu | %.3f | %.4f | %s | %s | %llu | %s |\n",
                fn_name(f), P::name, r.name.c_str(),
                static_cast<unsigned long long>(s.count), s.max_ulp,
                s.mean_ulp(), log2_text(s.max_rel).c_str(), worst,
                static_cast<unsigned long long>(s.not_correctly_rounded),
                ok ? "yes" : "NO");
    std::fflush(stdout);
  }
}

// from_int against the host's correctly rounded conversion, to_int against
// truncation, both for every `stride`-th value.
template <class P>
void conversion_rows(std::int64_t stride) {
  unsigned long long n = 0, bad = 0;
  for (std::int64_t i = INT32_MIN; i <= INT32_MAX; i += stride) {
    ++n;
    const float want = static_cast<float>(static_cast<std::int32_t>(i));
    if (bits_of(P::from_int(std::int32_t(i))) != bits_of(want)) ++bad;
  }
  const std::string every =
      stride == 1 ? std::string("all") : "every " + std::to_string(stride) + "-th";
  std::printf("| from_int | %s | %s int32 | %llu | mismatches: %llu |\n", P::name,
              every.c_str(), n, bad);
  n = 0;
  bad = 0;
  const Range r{"abs(x) < 2^31", -0x1p31f, 0x1.fffffep30f, stride};
  for_each_float(r, [&](float x) {
    ++n;
    if (P::to_int(x) != static_cast<std::int32_t>(x)) ++bad;
  });
  std::printf("| to_int | %s | %s float with %s | %llu | mismatches: %llu |\n", P::name,
              every.c_str(), r.name.c_str(), n, bad);
}

}  // namespace

int main(int argc, char** argv) {
  std::int64_t refine = 16;
  std::string only;
  bool libm = true;
  bool renderer_only = false;
  int level = -1;  // all
  int status = 0;
  std::vector<std::string> none;
  const bool go_on = minrt::cli::parse_tool(
      argc, argv, tool(), MINRT_VERSION,
      [&](const minrt::cli::Option* o, const std::string& v) -> std::string {
        const std::string name = o->name;
        if (name == "refine") {
          char* end = nullptr;
          refine = std::strtoll(v.c_str(), &end, 10);
          if (v.empty() || *end != 0 || refine < 1) return "bad --refine '" + v + "': expected N >= 1";
        } else if (name == "exhaustive") refine = std::int64_t(1) << 40;
        else if (name == "only") {
          only = v;
          if (only != "sqrt" && only != "floor" && only != "sin" && only != "cos" && only != "atan" && only != "conv")
            return "bad --only '" + only + "': expected sqrt, floor, sin, cos, atan or conv";
        } else if (name == "no-libm") libm = false;
        else if (name == "renderer") renderer_only = true;
        else if (name == "level") {
          if (v != "0" && v != "1" && v != "2") return "bad --level '" + v + "': expected 0, 1 or 2";
          level = v[0] - '0';
          libm = false;
        }
        return "";
      },
      status, &none);
  if (!go_on) return status;
  if (only != "conv") {
    std::printf("| function | policy | range | samples | max ULP | mean ULP | "
                "max rel err | worst arg | not CR | course rule |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---|\n");
  }
  for (Fn f : {Fn::sqrt, Fn::floor, Fn::sin, Fn::cos, Fn::atan}) {
    if (!only.empty() && only != fn_name(f)) continue;
    if (libm) table_rows<minrt::LibmFloat>(f, refine, renderer_only);
    if (level < 0 || level == 0) table_rows<minrt::PortableFloatT<0>>(f, refine, renderer_only);
    if (level < 0 || level == 1) table_rows<minrt::PortableFloatT<1>>(f, refine, renderer_only);
    if (level < 0 || level == 2) table_rows<minrt::PortableFloatT<2>>(f, refine, renderer_only);
  }
  if (only.empty() || only == "conv") {
    // Odd strides, so that every low bit pattern occurs.
    const std::int64_t stride = (4097 / refine) | 1;
    if (only.empty()) std::printf("\n");
    std::printf("| conversion | policy | values | count | result |\n|---|---|---|---:|---|\n");
    conversion_rows<minrt::PortableFloatT<2>>(stride);
  }
  return 0;
}
