#include "render_variants.hpp"

#include <cstdlib>
#include <memory>

#include "math_libm.hpp"
#if __has_include("math_portable.hpp")
#include "math_portable.hpp"
#define MINRT_HAVE_PORTABLE 1
#endif

namespace minrt::host {
namespace {

template <MathPolicy M>
RenderStatus run(ByteSource in, ByteSink out, const RenderOptions& options, Diagnostic& error,
                 const WarningSink& warnings) {
  const int width = valid_size(options.width, options.height) ? options.width : 1;
  const size_t bytes = arena_bytes_for_width<M>(width);
  void* buffer = std::malloc(bytes);
  if (buffer == nullptr) {
    error.text("cannot allocate ").number(static_cast<int64_t>(bytes)).text(" bytes");
    return RenderStatus::kOutOfMemory;
  }
  Arena arena(buffer, bytes);
  auto state = std::make_unique<RenderState<M>>();
  const RenderStatus st = render_sld<M>(in, out, options, *state, arena, error, warnings);
  std::free(buffer);
  return st;
}

}  // namespace

const char* variant_name(Variant v) {
  if (v.precision == Precision::kDouble) return v.shims == ShimSet::kLibm ? LibmDouble::name : nullptr;
  switch (v.shims) {
    case ShimSet::kLibm: return LibmFloat::name;
#ifdef MINRT_HAVE_PORTABLE
    case ShimSet::kPortable: return PortableFloat::name;
    case ShimSet::kPortableFast: return PortableFloatT<1>::name;
#endif
    default: return nullptr;
  }
}

RenderStatus render_variant(Variant v, ByteSource in, ByteSink out, const RenderOptions& options,
                            Diagnostic& error, const WarningSink& warnings) {
  if (v.precision == Precision::kDouble) return run<LibmDouble>(in, out, options, error, warnings);
  switch (v.shims) {
    case ShimSet::kLibm: return run<LibmFloat>(in, out, options, error, warnings);
#ifdef MINRT_HAVE_PORTABLE
    case ShimSet::kPortable: return run<PortableFloat>(in, out, options, error, warnings);
    case ShimSet::kPortableFast: return run<PortableFloatT<1>>(in, out, options, error, warnings);
#endif
    default: return RenderStatus::kBadOptions;
  }
}

}  // namespace minrt::host
