#include "isa_table.hpp"

namespace fwsim {

const char* class_name(InsnClass c) {
  static constexpr const char* kNames[] = {
      "alu", "mul", "div", "load", "store", "branch", "jump", "fp_add", "fp_mul", "fp_div", "fp_sqrt",
      "fp_convert", "fp_compare", "fp_move", "fp_fused", "fp_load", "fp_store", "csr", "system", "internal"};
  static_assert(sizeof(kNames) / sizeof(kNames[0]) == static_cast<size_t>(InsnClass::Count));
  return kNames[static_cast<size_t>(c)];
}

}  // namespace fwsim
