// The rendering variants the accuracy report compares, behind one plain
// interface (std types only), so that a variant may come from a translation
// unit compiled with different floating-point flags (see fma_variant.cpp).
#pragma once

#include <string>
#include <vector>

namespace minrt_accuracy {

struct Rendered {
  bool ok = false;
  std::string image;  // P6 bytes
  std::string error;  // one line when !ok
  std::vector<std::string> warnings;
};

using RenderFn = Rendered (*)(const std::string& sld, int width, int height);

struct Variant {
  const char* name;  // "double/libm", ...
  const char* tag;   // file-name form: "double-libm", ...
  RenderFn render;
};

// Every variant, the reference (double/libm) first.
const std::vector<Variant>& all_variants();
// nullptr when no variant has this name or tag.
const Variant* find_variant(const std::string& name_or_tag);

// float/portable compiled with multiply-add contraction (fma_variant.cpp).
Rendered render_portable_fma(const std::string& sld, int width, int height);
// False when this CPU cannot run that translation unit (x86 without FMA);
// render_portable_fma then fails with an error instead of trapping.
bool fma_variant_available();

}  // namespace minrt_accuracy
