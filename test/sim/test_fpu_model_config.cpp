// FPU model settings: the file format, the --fpu list, and their errors.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "fpu_model_config.hpp"

using fwsim::FpuModelConfig;

namespace {
std::string file_error(const std::string& text) {
  try {
    fwsim::parse_fpu_model(text, "team.cfg");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}

std::string list_error(const std::string& list) {
  FpuModelConfig c;
  try {
    fwsim::apply_fpu_settings(c, list);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "accepted";
}
}  // namespace

TEST_CASE("the default FPU model is IEEE", "[fpu-model]") {
  const FpuModelConfig c;
  CHECK(c.is_ieee());
  CHECK(fwsim::parse_fpu_model("# nothing but a comment\n\n", "x").is_ieee());
  CHECK(fwsim::describe(c).rfind("ieee", 0) == 0);
}

TEST_CASE("a model file sets every key", "[fpu-model]") {
  const FpuModelConfig c = fwsim::parse_fpu_model(
      "div = recip-mul   # x * 1/y\n"
      "recip_table_bits = 7\nrecip_entry_bits = 12\nrecip_newton_steps = 2\n"
      "sqrt = table-newton\nrsqrt_table_bits = 5\nrsqrt_entry_bits = 9\nrsqrt_newton_steps = 3\n"
      "mul = truncate\nadd = truncate\nsubnormals = flush\n",
      "team.cfg");
  CHECK(c.div == FpuModelConfig::Div::RecipMul);
  CHECK(c.recip_table_bits == 7);
  CHECK(c.recip_entry_bits == 12);
  CHECK(c.recip_newton_steps == 2);
  CHECK(c.sqrt == FpuModelConfig::Sqrt::TableNewton);
  CHECK(c.rsqrt_table_bits == 5);
  CHECK(c.rsqrt_entry_bits == 9);
  CHECK(c.rsqrt_newton_steps == 3);
  CHECK(c.mul == FpuModelConfig::Rounding::Truncate);
  CHECK(c.add == FpuModelConfig::Rounding::Truncate);
  CHECK(c.flush_subnormals);
  CHECK_FALSE(c.is_ieee());
  CHECK(fwsim::describe(c) ==
        "div=recip-mul(table 7 bits, entries 12 bits, 2 Newton steps) "
        "sqrt=table-newton(table 5 bits, entries 9 bits, 3 Newton steps) "
        "mul=truncate add=truncate subnormals=flush");
}

TEST_CASE("fpu option items apply in order on top of a configuration", "[fpu-model]") {
  FpuModelConfig c = fwsim::parse_fpu_model("div = recip-mul\nrecip_table_bits = 8\n", "f");
  fwsim::apply_fpu_settings(c, "recip_table_bits=12, recip_newton_steps = 0,sqrt=table-newton");
  CHECK(c.div == FpuModelConfig::Div::RecipMul);
  CHECK(c.recip_table_bits == 12);
  CHECK(c.recip_newton_steps == 0);
  CHECK(c.sqrt == FpuModelConfig::Sqrt::TableNewton);
  fwsim::apply_fpu_settings(c, "div=exact,sqrt=exact");
  CHECK(c.is_ieee());
}

TEST_CASE("bad model files name the file and line", "[fpu-model]") {
  CHECK(file_error("div = recip-mul\nbogus = 1\n") == "team.cfg:2: unknown key 'bogus'");
  CHECK(file_error("div recip-mul\n") == "team.cfg:1: expected `key = value`");
  CHECK(file_error("\n\ndiv = newton\n") == "team.cfg:3: unknown div 'newton' (exact, recip-mul)");
  CHECK(file_error("sqrt = fast\n") == "team.cfg:1: unknown sqrt 'fast' (exact, table-newton)");
  CHECK(file_error("mul = round\n") == "team.cfg:1: unknown mul 'round' (exact, truncate)");
  CHECK(file_error("subnormals = zero\n") == "team.cfg:1: unknown subnormals 'zero' (keep, flush)");
  CHECK(file_error("recip_table_bits = 17\n") ==
        "team.cfg:1: recip_table_bits must be an integer from 0 to 16, got '17'");
  CHECK(file_error("rsqrt_table_bits = 0\n") ==
        "team.cfg:1: rsqrt_table_bits must be an integer from 1 to 16, got '0'");
  CHECK(file_error("recip_entry_bits = 0\n").find("from 1 to 23") != std::string::npos);
  CHECK(file_error("recip_newton_steps = 5\n").find("from 0 to 4") != std::string::npos);
  CHECK(file_error("rsqrt_newton_steps = -1\n").find("got '-1'") != std::string::npos);
  CHECK(file_error("recip_table_bits = 8x\n").find("got '8x'") != std::string::npos);
  CHECK(file_error("div =\n") == "team.cfg:1: missing value for div");
}

TEST_CASE("bad fpu option items are named in the error", "[fpu-model]") {
  CHECK(list_error("div=recip-mul,recip_table_bits=99") ==
        "--fpu 'recip_table_bits=99': recip_table_bits must be an integer from 0 to 16, got '99'");
  CHECK(list_error("div=recip-mul,,sqrt=exact") == "--fpu '': expected `key = value`");
  CHECK(list_error("div=recip-mul,") == "--fpu '': expected `key = value`");
  CHECK(list_error("frobnicate=1") == "--fpu 'frobnicate=1': unknown key 'frobnicate'");
  CHECK(list_error("=3") == "--fpu '=3': missing key before '='");
  CHECK(list_error("") == "--fpu needs key=value items");
}
