#include "fpu_model_config.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace fwsim {
namespace {

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// Sets one key; returns an error text (empty when accepted).
std::string set_key(FpuModelConfig& c, const std::string& key, const std::string& value) {
  auto number = [&](unsigned lo, unsigned hi, unsigned& out) -> std::string {
    char* end = nullptr;
    const bool digits = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
    const unsigned long v = digits ? std::strtoul(value.c_str(), &end, 10) : 0;
    if (!digits || v < lo || v > hi)
      return key + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
             ", got '" + value + "'";
    out = static_cast<unsigned>(v);
    return "";
  };
  auto rounding = [&](FpuModelConfig::Rounding& out) -> std::string {
    if (value == "exact") out = FpuModelConfig::Rounding::Exact;
    else if (value == "truncate") out = FpuModelConfig::Rounding::Truncate;
    else return "unknown " + key + " '" + value + "' (exact, truncate)";
    return "";
  };
  if (key == "div") {
    if (value == "exact") c.div = FpuModelConfig::Div::Exact;
    else if (value == "recip-mul") c.div = FpuModelConfig::Div::RecipMul;
    else return "unknown div '" + value + "' (exact, recip-mul)";
    return "";
  }
  if (key == "sqrt") {
    if (value == "exact") c.sqrt = FpuModelConfig::Sqrt::Exact;
    else if (value == "table-newton") c.sqrt = FpuModelConfig::Sqrt::TableNewton;
    else return "unknown sqrt '" + value + "' (exact, table-newton)";
    return "";
  }
  if (key == "mul") return rounding(c.mul);
  if (key == "add") return rounding(c.add);
  if (key == "subnormals") {
    if (value == "keep") c.flush_subnormals = false;
    else if (value == "flush") c.flush_subnormals = true;
    else return "unknown subnormals '" + value + "' (keep, flush)";
    return "";
  }
  if (key == "recip_table_bits") return number(0, 16, c.recip_table_bits);
  if (key == "recip_entry_bits") return number(1, 23, c.recip_entry_bits);
  if (key == "recip_newton_steps") return number(0, 4, c.recip_newton_steps);
  if (key == "rsqrt_table_bits") return number(1, 16, c.rsqrt_table_bits);
  if (key == "rsqrt_entry_bits") return number(1, 23, c.rsqrt_entry_bits);
  if (key == "rsqrt_newton_steps") return number(0, 4, c.rsqrt_newton_steps);
  return "unknown key '" + key + "'";
}

// Splits "key = value"; returns an error text or "".
std::string split_setting(const std::string& s, std::string& key, std::string& value) {
  const size_t eq = s.find('=');
  if (eq == std::string::npos) return "expected `key = value`";
  key = trim(s.substr(0, eq));
  value = trim(s.substr(eq + 1));
  if (key.empty()) return "missing key before '='";
  if (value.empty()) return "missing value for " + key;
  return "";
}

const char* rounding_name(FpuModelConfig::Rounding r) {
  return r == FpuModelConfig::Rounding::Exact ? "exact" : "truncate";
}

std::string steps(unsigned n) { return std::to_string(n) + (n == 1 ? " Newton step" : " Newton steps"); }

}  // namespace

FpuModelConfig parse_fpu_model(const std::string& text, const std::string& origin) {
  FpuModelConfig c;
  std::istringstream in(text);
  std::string raw;
  for (int lineno = 1; std::getline(in, raw); ++lineno) {
    const std::string s = trim(raw.substr(0, raw.find('#')));
    if (s.empty()) continue;
    std::string key, value;
    std::string err = split_setting(s, key, value);
    if (err.empty()) err = set_key(c, key, value);
    if (!err.empty()) throw std::runtime_error(origin + ":" + std::to_string(lineno) + ": " + err);
  }
  return c;
}

void apply_fpu_settings(FpuModelConfig& cfg, const std::string& list) {
  if (trim(list).empty()) throw std::runtime_error("--fpu needs key=value items");
  size_t pos = 0;
  while (pos <= list.size()) {
    const size_t comma = std::min(list.find(',', pos), list.size());
    const std::string item = trim(list.substr(pos, comma - pos));
    std::string key, value;
    std::string err = split_setting(item, key, value);
    if (err.empty()) err = set_key(cfg, key, value);
    if (!err.empty()) throw std::runtime_error("--fpu '" + item + "': " + err);
    pos = comma + 1;
  }
}

std::string describe(const FpuModelConfig& c) {
  if (c.is_ieee()) return "ieee (exact IEEE 754 single precision)";
  std::string s = "div=";
  if (c.div == FpuModelConfig::Div::Exact) s += "exact";
  else
    s += "recip-mul(table " + std::to_string(c.recip_table_bits) + " bits, entries " +
         std::to_string(c.recip_entry_bits) + " bits, " + steps(c.recip_newton_steps) + ")";
  s += " sqrt=";
  if (c.sqrt == FpuModelConfig::Sqrt::Exact) s += "exact";
  else
    s += "table-newton(table " + std::to_string(c.rsqrt_table_bits) + " bits, entries " +
         std::to_string(c.rsqrt_entry_bits) + " bits, " + steps(c.rsqrt_newton_steps) + ")";
  s += std::string(" mul=") + rounding_name(c.mul) + " add=" + rounding_name(c.add) +
       " subnormals=" + (c.flush_subnormals ? "flush" : "keep");
  return s;
}

}  // namespace fwsim
