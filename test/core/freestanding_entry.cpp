// One render through the core for the freestanding link check: the byte I/O
// is a pair of function pointers, so the only external symbols left are
// those of the math policy and the compiler's memory routines.
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "render/minrt/render.hpp"

namespace {
alignas(16) unsigned char g_arena[1 << 20];
minrt::RenderState<POLICY> g_state;
int read_byte(void*) { return -1; }
void write_bytes(void*, const uint8_t*, size_t) {}
}  // namespace

extern "C" int minrt_entry() {
  minrt::Arena arena(g_arena, sizeof g_arena);
  minrt::Diagnostic error;
  return static_cast<int>(minrt::render_sld<POLICY>(minrt::ByteSource{&read_byte, nullptr},
                                                    minrt::ByteSink{&write_bytes, nullptr}, {},
                                                    g_state, arena, error));
}
