// The roughness normals' random values (render/general/sampling.hpp) are
// standard normal: mean, variance, a Kolmogorov-Smirnov and a chi-squared
// test of the values against N(0, 1), the three components' independence
// (their squared length is chi-squared with 3 degrees of freedom), and the
// spread of the perturbed normals against normals perturbed with the C++
// library's own normal values. Each policy the tracer runs in draws them:
// double, float, and the board's portable float. The same checks are shown
// to fail for wrong samplers (scaled by 1.1, Box-Muller without its log, a
// lost or misshapen tail), so they can tell. Fixed seeds: the verdicts are reproducible.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/counter_rng.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "core/math/vec3.hpp"
#include "render/general/sampling.hpp"

namespace {

using minrt::CounterRng;
using minrt::Vec3;

constexpr double kPi = 3.14159265358979323846;
constexpr int kPixels = 1 << 16;  // streams; 8 triples each: 524,288 triples

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }
// P(chi^2 with 3 degrees of freedom <= t).
double chi2_3_cdf(double t) {
  return t <= 0 ? 0 : std::erf(std::sqrt(t / 2)) - std::sqrt(2 * t / kPi) * std::exp(-t / 2);
}

// Triples drawn as the tracer draws them: per pixel stream, several hits
// in a row and the forked stream of each one's reflection.
template <class M>
std::vector<Vec3<double>> draw_triples() {
  std::vector<Vec3<double>> out;
  out.reserve(static_cast<std::size_t>(kPixels) * 8);
  for (uint32_t p = 0; p < kPixels; ++p) {
    CounterRng rng(418, p);
    for (int s = 0; s < 4; ++s) {
      const auto g = minrt::general::gaussian3<M>(rng);
      out.push_back({double(g.x), double(g.y), double(g.z)});
      CounterRng child = rng.fork(1);
      const auto c = minrt::general::gaussian3<M>(child);
      out.push_back({double(c.x), double(c.y), double(c.z)});
    }
  }
  return out;
}

std::vector<double> components(const std::vector<Vec3<double>>& t) {
  std::vector<double> v;
  v.reserve(3 * t.size());
  for (const auto& g : t) v.insert(v.end(), {g.x, g.y, g.z});
  return v;
}

// sqrt(n) times the largest distance between the sample's CDF and `cdf`:
// above 1.95 for a right distribution with probability 0.001.
double ks_scaled(std::vector<double> v, const std::function<double(double)>& cdf) {
  std::sort(v.begin(), v.end());
  const double n = double(v.size());
  double d = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double f = cdf(v[i]);
    d = std::max({d, f - double(i) / n, double(i + 1) / n - f});
  }
  return d * std::sqrt(n);
}

// The same for two samples.
double ks_two_sample_scaled(std::vector<double> a, std::vector<double> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = double(a.size()), nb = double(b.size());
  std::size_t i = 0, j = 0;
  double d = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    d = std::max(d, std::abs(double(i) / na - double(j) / nb));
  }
  return d * std::sqrt(na * nb / (na + nb));
}

// Chi-squared of the counts in bins of width 0.25 from -4 to 4 and the two
// tails beyond (34 bins, 33 degrees of freedom: above 70 with probability
// 2e-4 for a right distribution).
double chi2_bins(const std::vector<double>& v) {
  constexpr int kInner = 32;
  std::vector<double> count(kInner + 2, 0);
  for (double x : v) {
    const int b = x < -4 ? 0 : x >= 4 ? kInner + 1 : 1 + std::min(kInner - 1, int(std::floor((x + 4) * 4)));
    count[b] += 1;
  }
  double chi2 = 0;
  for (int b = 0; b < kInner + 2; ++b) {
    const double lo = b == 0 ? -INFINITY : -4 + (b - 1) * 0.25;
    const double hi = b == kInner + 1 ? INFINITY : -4 + b * 0.25;
    const double expected = double(v.size()) * (normal_cdf(hi) - normal_cdf(lo));
    chi2 += (count[b] - expected) * (count[b] - expected) / expected;
  }
  return chi2;
}

struct NormalStats {
  double n, mean, var, ks, chi2;
  // Empty when every test of a standard normal sample passes, else what
  // failed.
  std::string failures() const {
    std::ostringstream why;
    if (!(std::abs(mean) < 5 / std::sqrt(n))) why << "mean; ";
    if (!(std::abs(var - 1) < 5 * std::sqrt(2 / n))) why << "variance; ";
    if (!(ks < 1.95)) why << "KS; ";
    if (!(chi2 < 70)) why << "chi2; ";
    return why.str();
  }
};

std::ostream& operator<<(std::ostream& o, const NormalStats& s) {
  return o << "n " << s.n << ", mean " << s.mean << ", variance " << s.var << ", KS sqrt(n) D " << s.ks
           << ", chi2 " << s.chi2;
}

NormalStats stats_of(const std::vector<double>& v) {
  const double n = double(v.size());
  double sum = 0, sum2 = 0;
  for (double x : v) sum += x, sum2 += x * x;
  const double mean = sum / n;
  return {n, mean, sum2 / n - mean * mean, ks_scaled(v, normal_cdf), chi2_bins(v)};
}

std::string standard_normal_failures(const std::vector<double>& v) { return stats_of(v).failures(); }

// The ziggurat's tail (about 1 value in 1,760 comes from it) is too rare to
// be judged in the values above: sqrt(n) times the KS distance of tail
// samples from the normal beyond the tail start r, P(X <= x | X > r).
double tail_ks(const std::vector<double>& v) {
  const double r = minrt::normal_tables::kTailStart;
  const double beyond_r = std::erfc(r / std::sqrt(2.0));
  return ks_scaled(v, [&](double x) { return x <= r ? 0.0 : 1 - std::erfc(x / std::sqrt(2.0)) / beyond_r; });
}
constexpr int kTailSamples = 100000;

template <class M>
void check_policy() {
  const auto t = draw_triples<M>();
  const auto v = components(t);
  const NormalStats s = stats_of(v);
  INFO(M::name << ": " << s);
  CHECK(s.failures().empty());

  // Each component alone, and no correlation between them.
  const double n = double(t.size());
  double m[3] = {}, c[3] = {};
  for (const auto& g : t) {
    m[0] += g.x, m[1] += g.y, m[2] += g.z;
    c[0] += g.x * g.y, c[1] += g.y * g.z, c[2] += g.z * g.x;
  }
  for (int k = 0; k < 3; ++k) {
    CHECK(std::abs(m[k] / n) < 5 / std::sqrt(n));
    CHECK(std::abs(c[k] / n) < 5 / std::sqrt(n));
  }
  // Jointly: |g|^2 ~ chi^2(3).
  std::vector<double> len2;
  len2.reserve(t.size());
  for (const auto& g : t) len2.push_back(g.x * g.x + g.y * g.y + g.z * g.z);
  CHECK(ks_scaled(len2, chi2_3_cdf) < 1.95);

  std::vector<double> tail;
  CounterRng rng(418, kPixels);
  for (int i = 0; i < kTailSamples; ++i) tail.push_back(double(minrt::general::normal_detail::tail<M>(rng)));
  CHECK(tail_ks(tail) < 1.95);
}

// cos of the angle between n = (0, 1, 0) and n' = norm(n + sigma g).
std::vector<double> spread(const std::vector<Vec3<double>>& t, double sigma) {
  std::vector<double> out;
  out.reserve(t.size());
  for (const auto& g : t) {
    const Vec3<double> p{sigma * g.x, 1 + sigma * g.y, sigma * g.z};
    out.push_back(p.y / std::sqrt(dot(p, p)));
  }
  return out;
}

std::vector<Vec3<double>> library_triples(std::size_t count) {
  std::mt19937_64 gen(20261127);
  std::normal_distribution<double> g;
  std::vector<Vec3<double>> out(count);
  for (auto& v : out) {
    v.x = g(gen);
    v.y = g(gen);
    v.z = g(gen);
  }
  return out;
}

}  // namespace

TEST_CASE("normal sampling: standard normal in every policy", "[cs418][roughness][sampling]") {
  check_policy<minrt::LibmDouble>();
  check_policy<minrt::LibmFloat>();
  check_policy<minrt::PortableFloat>();
}

TEST_CASE("normal sampling: the checks fail for wrong samplers", "[cs418][roughness][sampling]") {
  const auto good = components(draw_triples<minrt::LibmDouble>());
  REQUIRE(standard_normal_failures(good).empty());

  std::vector<double> scaled = good;
  for (double& x : scaled) x *= 1.1;
  INFO("scaled by 1.1: " << stats_of(scaled));
  CHECK_FALSE(standard_normal_failures(scaled).empty());

  // Every value beyond the ziggurat's tail start pulled back to it.
  const double r = minrt::normal_tables::kTailStart;
  std::vector<double> no_tail = good;
  for (double& x : no_tail) x = std::max(-r, std::min(r, x));
  INFO("no tail: " << stats_of(no_tail));
  CHECK_FALSE(standard_normal_failures(no_tail).empty());

  // A tail of r plus an exponential without the rejection step that
  // shapes it.
  std::vector<double> exponential_tail;
  CounterRng rng(418, kPixels);
  for (int i = 0; i < kTailSamples; ++i)
    exponential_tail.push_back(r - std::log(1 - rng.uniform<minrt::LibmDouble>()) / r);
  CHECK(tail_ks(exponential_tail) > 1.95);

  // Box-Muller with the log replaced by its first-order term:
  // radius sqrt(2 (1 - u)) instead of sqrt(-2 log u).
  std::vector<double> no_log;
  no_log.reserve(good.size());
  for (uint32_t p = 0; no_log.size() < good.size(); ++p) {
    CounterRng rng(418, p);
    const double u1 = 1 - rng.uniform<minrt::LibmDouble>(), u2 = rng.uniform<minrt::LibmDouble>();
    const double radius = std::sqrt(2 * (1 - u1));
    no_log.push_back(radius * std::cos(2 * kPi * u2));
    no_log.push_back(radius * std::sin(2 * kPi * u2));
  }
  INFO("Box-Muller without log: " << stats_of(no_log));
  CHECK_FALSE(standard_normal_failures(no_log).empty());

  // The same Box-Muller with its log is right (the checks are not merely
  // strict).
  std::vector<double> box_muller;
  box_muller.reserve(good.size());
  for (uint32_t p = 0; box_muller.size() < good.size(); ++p) {
    CounterRng rng(418, p);
    const double u1 = 1 - rng.uniform<minrt::LibmDouble>(), u2 = rng.uniform<minrt::LibmDouble>();
    const double radius = std::sqrt(-2 * std::log(u1));
    box_muller.push_back(radius * std::cos(2 * kPi * u2));
    box_muller.push_back(radius * std::sin(2 * kPi * u2));
  }
  INFO("Box-Muller: " << stats_of(box_muller));
  CHECK(standard_normal_failures(box_muller).empty());
}

TEST_CASE("normal sampling: rough normals spread as with the library's normal values",
          "[cs418][roughness][sampling]") {
  const auto ours = draw_triples<minrt::PortableFloat>();
  const auto library = library_triples(ours.size());
  for (double sigma : {0.05, 0.2, 1.0}) {
    INFO("roughness " << sigma);
    const auto a = spread(ours, sigma), b = spread(library, sigma);
    CHECK(ks_two_sample_scaled(a, b) < 1.95);
    // A roughness 10 % too large is told apart.
    CHECK(ks_two_sample_scaled(spread(ours, 1.1 * sigma), b) > 1.95);
  }
}
