// The outcome of reading one number from a value source (the SLD reader's
// text or the course protocol's words; see formats/sld/sld_values.hpp).
#pragma once

namespace minrt {

enum class ValueStatus { kOk, kEnd, kTooLong, kInvalid, kOutOfRange, kNonFinite };

}  // namespace minrt
