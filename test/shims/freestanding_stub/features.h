/* Stand-in for glibc's <features.h> in the riscv32 freestanding compile check
   (test/shims/CMakeLists.txt).  The host libstdc++ headers are the only C++
   headers on this machine; their x86_64 configuration header includes
   <features.h> and tests __GLIBC_PREREQ, and nothing else from the C library
   is reached by the freestanding headers (<bit>, <concepts>, <cstdint>,
   <limits>) that core/math_portable.hpp uses. */
#pragma once
#define __GLIBC_PREREQ(maj, min) 0
