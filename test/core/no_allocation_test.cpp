// The core allocates nothing: everything comes from the RenderState and the
// arena the caller hands in. Global operator new is counted while it runs.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "render/sld/render.hpp"
#include "test_support.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// These replacements are malloc and free underneath: GCC cannot see that
// every new here is the matching one and warns on each free.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
// The array and nothrow forms too, so every allocation is counted and every
// pair matches (AddressSanitizer reports new[] from its own allocator freed by
// this free as a mismatch).
void* operator new[](std::size_t n) { return ::operator new(n); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return ::operator new(n, t); }

namespace {

void count_bytes(void* ctx, const uint8_t*, size_t n) { *static_cast<size_t*>(ctx) += n; }

template <minrt::MathPolicy M>
void check_no_allocation(const std::string& sld) {
  const size_t bytes = minrt::arena_bytes_for_width<M>(64);
  std::unique_ptr<unsigned char[]> buffer(new unsigned char[bytes]);
  auto state = std::make_unique<minrt::RenderState<M>>();
  minrt::Arena arena(buffer.get(), bytes);
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  size_t written = 0;
  minrt::RenderOptions options;
  options.width = 64;
  options.height = 64;
  minrt::Diagnostic error;
  const long before = g_allocations.load();
  const auto st = minrt::render_sld<M>(src.source(), minrt::ByteSink{&count_bytes, &written},
                                       options, *state, arena, error);
  const long during = g_allocations.load() - before;
  REQUIRE(st == minrt::RenderStatus::kOk);
  CHECK(during == 0);
  CHECK(written > 64 * 64 * 6);
  CHECK(arena.used() <= bytes);
  CHECK(arena.used() > 0);
}

}  // namespace

TEST_CASE("core: rendering allocates nothing beyond the caller's arena", "[alloc]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string sld = minrt::test::read_file(minrt::test::shared_dir() + "/scenes/contest.sld");
  check_no_allocation<minrt::LibmDouble>(sld);
  check_no_allocation<minrt::PortableFloat>(sld);
}

TEST_CASE("core: a too small arena is reported, not overrun", "[alloc]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string sld = minrt::test::read_file(minrt::test::shared_dir() + "/scenes/contest.sld");
  unsigned char small[4096];
  auto state = std::make_unique<minrt::RenderState<minrt::LibmDouble>>();
  minrt::Arena arena(small, sizeof small);
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  size_t written = 0;
  minrt::Diagnostic error;
  const auto st = minrt::render_sld<minrt::LibmDouble>(
      src.source(), minrt::ByteSink{&count_bytes, &written}, {}, *state, arena, error);
  CHECK(st == minrt::RenderStatus::kOutOfMemory);
  CHECK(written == 0);
  CHECK(std::string(error.message).find("out of memory: this scene needs") == 0);
}
