#include "variants.hpp"

#include "render_variants.hpp"

namespace minrt_accuracy {
namespace {

void append(void* ctx, const uint8_t* data, size_t size) {
  static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(data), size);
}

void collect_warning(void* ctx, const minrt::Diagnostic& d) {
  static_cast<std::vector<std::string>*>(ctx)->push_back(d.message);
}

template <minrt::host::Precision P, minrt::host::ShimSet S>
Rendered render_host(const std::string& sld, int width, int height) {
  Rendered r;
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  minrt::RenderOptions options;
  options.width = width;
  options.height = height;
  options.format = minrt::PpmFormat::kP6;
  minrt::Diagnostic error;
  const auto status = minrt::host::render_variant(
      minrt::host::Variant{P, S}, src.source(), minrt::ByteSink{&append, &r.image}, options, error,
      minrt::WarningSink{&collect_warning, &r.warnings});
  r.ok = status == minrt::RenderStatus::kOk;
  if (!r.ok) r.error = error.message;
  return r;
}

using minrt::host::Precision;
using minrt::host::ShimSet;

}  // namespace

const std::vector<Variant>& all_variants() {
  static const std::vector<Variant> list = {
      {"double/libm", "double-libm", &render_host<Precision::kDouble, ShimSet::kLibm>},
      {"float/libm", "float-libm", &render_host<Precision::kFloat, ShimSet::kLibm>},
      {"float/portable", "float-portable", &render_host<Precision::kFloat, ShimSet::kPortable>},
      {"float/portable-fast", "float-portable-fast",
       &render_host<Precision::kFloat, ShimSet::kPortableFast>},
      {"float/portable-min", "float-portable-min",
       &render_host<Precision::kFloat, ShimSet::kPortableMin>},
      {"float/portable+fma", "float-portable-fma", &render_portable_fma},
  };
  return list;
}

const Variant* find_variant(const std::string& name_or_tag) {
  for (const Variant& v : all_variants())
    if (name_or_tag == v.name || name_or_tag == v.tag) return &v;
  return nullptr;
}

}  // namespace minrt_accuracy
