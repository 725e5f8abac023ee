// std::bit_cast for the freestanding layers: the bare-metal build has the
// compiler but no C++ library headers, so <bit> is not there. Both clang and
// gcc implement std::bit_cast with this builtin.
#pragma once

namespace minrt {

template <class To, class From>
constexpr To bit_cast(const From& from) {
  static_assert(sizeof(To) == sizeof(From), "bit_cast needs types of one size");
  return __builtin_bit_cast(To, from);
}

}  // namespace minrt
