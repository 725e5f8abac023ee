// float/portable with multiply-add contraction allowed. This file alone is
// compiled with -ffp-contract=fast (and -mfma on x86-64), see CMakeLists.txt,
// so the compiler may turn a*b+c anywhere in the renderer and the shims into
// one fused multiply-add with a single rounding.
//
// The core is header-only and the rest of the program instantiates the same
// templates without contraction. To keep the two sets of instantiations from
// being merged by the linker (same mangled names, different code), every core
// header is included here with its namespace renamed.
#include <cstdlib>
#include <memory>

#include "variants.hpp"

#define minrt minrt_fma_build
#include "core/math/math_portable.hpp"
#include "render/sld/render.hpp"
#undef minrt

namespace minrt_accuracy {
namespace {

namespace core = minrt_fma_build;

// The FMA-contracted copy of PortableFloat, under its own name.
struct PortableFloatFma : core::PortableFloat {
  static constexpr const char* name = "float/portable+fma";
};
static_assert(core::MathPolicy<PortableFloatFma>);

void append(void* ctx, const uint8_t* data, size_t size) {
  static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(data), size);
}

void collect_warning(void* ctx, const core::Diagnostic& d) {
  static_cast<std::vector<std::string>*>(ctx)->push_back(d.message);
}

}  // namespace

bool fma_variant_available() {
#if defined(__x86_64__) && defined(__FMA__)
  return __builtin_cpu_supports("fma");
#else
  return true;
#endif
}

Rendered render_portable_fma(const std::string& sld, int width, int height) {
  using M = PortableFloatFma;
  Rendered r;
  if (!fma_variant_available()) {
    r.error = "this CPU has no FMA instructions";
    return r;
  }
  core::RenderOptions options;
  options.width = width;
  options.height = height;
  options.format = core::PpmFormat::kP6;
  const int arena_width = core::valid_size(width, height) ? width : 1;
  const size_t bytes = core::arena_bytes_for_width<M>(arena_width);
  std::unique_ptr<unsigned char, decltype(&std::free)> buffer(
      static_cast<unsigned char*>(std::malloc(bytes)), &std::free);
  if (!buffer) {
    r.error = "cannot allocate the arena";
    return r;
  }
  core::Arena arena(buffer.get(), bytes);
  auto state = std::make_unique<core::RenderState<M>>();
  core::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  core::Diagnostic error;
  const auto status = core::render_sld<M>(src.source(), core::ByteSink{&append, &r.image}, options,
                                          *state, arena, error,
                                          core::WarningSink{&collect_warning, &r.warnings});
  r.ok = status == core::RenderStatus::kOk;
  if (!r.ok) r.error = error.message;
  return r;
}

}  // namespace minrt_accuracy
