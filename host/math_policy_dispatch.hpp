// The one place a run-time Variant (render_variants.hpp) becomes a math
// policy type. A header of its own: the libm policy declares the libm
// functions itself, so only the files that instantiate the tracers include
// it.
#pragma once

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "render_variants.hpp"

namespace minrt::host {

// Calls f.template operator()<M>() with the policy M of `v` and returns
// true, or returns false without calling f when the combination is not
// built.
template <class F>
bool with_math_policy(Variant v, F&& f) {
  if (v.precision == Precision::kDouble) {
    if (v.shims != ShimSet::kLibm) return false;
    f.template operator()<LibmDouble>();
    return true;
  }
  switch (v.shims) {
    case ShimSet::kLibm: f.template operator()<LibmFloat>(); return true;
    case ShimSet::kPortable: f.template operator()<PortableFloat>(); return true;
    case ShimSet::kPortableFast: f.template operator()<PortableFloatFast>(); return true;
    case ShimSet::kPortableMin: f.template operator()<PortableFloatMin>(); return true;
  }
  return false;
}

}  // namespace minrt::host
