#include "host_fma.hpp"

namespace fwsim {

#if defined(__x86_64__)
const bool kHostHasFma = __builtin_cpu_supports("fma");
#else
const bool kHostHasFma = false;
#endif

}  // namespace fwsim
