#include "render_variants.hpp"

#include <memory>
#include <new>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "math_policy_dispatch.hpp"
#include "minrt_parallel.hpp"
#include "protocol/course_word_values.hpp"

namespace minrt::host {
namespace {

// `make.template operator()<R>()` gives the scene's value source for real type R.
template <MathPolicy M, class MakeValues>
RenderStatus run(const MakeValues& make, const RowSink& out, const RenderOptions& options, Diagnostic& error,
                 const WarningSink& warnings, int threads, const RowSink* finished) {
  // The one allocation: sized from the limits and the width, before reading
  // (with the slot rows of rendering in bands, render_minrt_parallel).
  const int width = valid_size(options.width, options.height) ? options.width : 1;
  const size_t bytes = arena_bytes_for_width<M>(width) + Tracer<M>::band_bytes(width);
  std::unique_ptr<unsigned char[]> buffer(new (std::nothrow) unsigned char[bytes]);
  auto state = std::unique_ptr<RenderState<M>>(new (std::nothrow) RenderState<M>());
  if (buffer == nullptr || state == nullptr) {
    error.text("cannot allocate ").number(static_cast<int64_t>(bytes)).text(" bytes");
    return RenderStatus::kOutOfMemory;
  }
  Arena arena(buffer.get(), bytes);
  const RenderStatus st =
      prepare_sld<M>(make.template operator()<typename M::real>(), options, *state, arena, error, warnings);
  if (st != RenderStatus::kOk) return st;
  threads = minrt_thread_count(threads, options.height);
  if (threads == 1) {
    state->tracer.render(out);
  } else if (!state->tracer.prepare_bands(arena) ||
             !render_minrt_parallel<M>(state->tracer, state->scene, options.width, options.height, threads, out,
                                       finished)) {
    error.text("cannot allocate memory for ").number(threads).text(" threads");
    return RenderStatus::kOutOfMemory;
  }
  return RenderStatus::kOk;
}

template <class MakeValues>
RenderStatus dispatch(Variant v, const MakeValues& make, const RowSink& out, const RenderOptions& options,
                      Diagnostic& error, const WarningSink& warnings, int threads,
                      const RowSink* finished = nullptr) {
  RenderStatus status = RenderStatus::kBadOptions;
  if (!with_math_policy(v, [&]<class M>() { status = run<M>(make, out, options, error, warnings, threads, finished); }))
    error.text("this precision and shim combination is not built");
  return status;
}

}  // namespace

const char* variant_name(Variant v) {
  const char* name = nullptr;
  with_math_policy(v, [&]<class M>() { name = M::name; });
  return name;
}

RenderStatus render_variant(Variant v, ByteSource in, ByteSink out, const RenderOptions& options,
                            Diagnostic& error, const WarningSink& warnings, int threads, const RowSink* finished) {
  PpmWriter ppm(out, options.format);
  return render_variant_rows(v, in, ppm.sink(), options, error, warnings, threads, finished);
}

RenderStatus render_variant_rows(Variant v, ByteSource in, const RowSink& out, const RenderOptions& options,
                                 Diagnostic& error, const WarningSink& warnings, int threads,
                                 const RowSink* finished) {
  return dispatch(v, [&]<class R>() { return SldTextValues<R>(in); }, out, options, error, warnings, threads,
                  finished);
}

RenderStatus render_variant_course_words(Variant v, ByteSource words, bool big_endian, ByteSink out,
                                         const RenderOptions& options, Diagnostic& error,
                                         const WarningSink& warnings) {
  const auto endian = big_endian ? send::course::Endian::kBig : send::course::Endian::kLittle;
  PpmWriter ppm(out, options.format);
  return dispatch(
      v, [&]<class R>() { return send::course::CourseWordValues<R>(words, endian); }, ppm.sink(), options, error,
      warnings, 1);
}

}  // namespace minrt::host
