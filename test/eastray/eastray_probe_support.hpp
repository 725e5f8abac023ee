// Shared helpers of the EASTRAY probe tests (eastray_probe_*_test.cpp):
// rendering scene text in-process, pixels, image comparison, running
// minrt, and quadric algebra used to write a kind's general-quadric (kind 0)
// form and a chain of moves as one :mtx.
#pragma once

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "format_sides/eastray_host.hpp"
#include "render_driver.hpp"
#include "test_support.hpp"

namespace minrt::test {

// An EASTRAY scene rendered in memory by minrt's driver, as RGB.
struct EastrayImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;      // 3 bytes a pixel, top row first
  std::string output_statement;  // where the scene's `output` sends the image, if it names it
};

inline bool render_eastray(const std::string& path, const std::string& text, minrt::host::Variant v,
                           EastrayImage& img, std::string& error) {
  minrt::host::DriverOptions o;
  o.variant = v;
  o.quiet = true;
  minrt::host::RenderedScene r;
  const std::size_t slash = path.rfind('/');
  const minrt::host::SceneInput in{path, path, slash == std::string::npos ? "" : path.substr(0, slash + 1), text};
  if (!minrt::host::render_in_memory(minrt::formats::format_of(minrt::formats::FormatId::kEastray), in, o, r, error))
    return false;
  img.width = r.image.width;
  img.height = r.image.height;
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(img.width) * img.height; i < n; ++i)
    for (int c = 0; c < 3; ++c) img.rgb[3 * i + c] = r.image.rgba[4 * i + c];
  img.output_statement = r.output_name;
  return true;
}

}  // namespace minrt::test

namespace eprobe {

using minrt::test::EastrayImage;
using minrt::test::render_eastray;


struct Rgb {
  int r, g, b;
};

inline EastrayImage render(const std::string& text, const std::string& path = "probe.ray",
                           minrt::host::Variant v = {}) {
  EastrayImage img;
  std::string error;
  const bool ok = render_eastray(path, text, v, img, error);
  INFO(error);
  REQUIRE(ok);
  return img;
}

inline Rgb px(const EastrayImage& im, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * im.width + x) * 3;
  return Rgb{im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}

// Pixels whose largest channel difference exceeds `tol` (SPEC.md's
// deterministic metric: max_channel |delta| > tol).
inline int differing(const EastrayImage& a, const EastrayImage& b, int tol = 2) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  int n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    bool off = false;
    for (int c = 0; c < 3; ++c) off = off || std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) > tol;
    n += off ? 1 : 0;
  }
  return n;
}

// Pixels that are not the background colour `bg` (a guard that a pair
// compares pictures with something in them).
inline int covered(const EastrayImage& a, Rgb bg) {
  int n = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3)
    n += (a.rgb[i] != bg.r || a.rgb[i + 1] != bg.g || a.rgb[i + 2] != bg.b) ? 1 : 0;
  return n;
}

// The byte a shaded value becomes: value x 255, clamped, truncated. A probe
// whose value lands within 0.02 of a whole byte accepts either neighbour.
inline bool byte_is(int got, double value) {
  const double x = std::fmin(255.0, std::fmax(0.0, value * 255.0));
  const int lo = static_cast<int>(std::floor(x - 0.02)), hi = static_cast<int>(std::floor(x + 0.02));
  return got >= std::max(0, lo) && got <= std::min(255, hi);
}

inline std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// With EPROBE_DUMP=DIR set, each pair's two scenes are written there as
// NNN-a.ray and NNN-b.ray, to render and look at.
inline void dump_pair(const std::string& a, const std::string& b) {
  const char* dir = std::getenv("EPROBE_DUMP");
  if (dir == nullptr) return;
  static int count = 0;
  char name[32];
  std::snprintf(name, sizeof name, "/%03d", count++);
  std::ofstream(std::string(dir) + name + "-a.ray", std::ios::binary) << a;
  std::ofstream(std::string(dir) + name + "-b.ray", std::ios::binary) << b;
}

// ---------------------------------------------------------------- processes

using Run = minrt::test::CommandRun;

inline Run run(const std::string& cmd_line, const std::string& cwd) {
  return minrt::test::run_in_dir(cwd, cmd_line);
}

inline std::string temp_dir() { return minrt::test::temp_dir("eprobe"); }

inline void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

// --------------------------------------------------------------- algebra

using Vec3 = std::array<double, 3>;

// An affine map x -> L x + t, as the manual's moves build it (line 1255:
// the command nearest the object applies first, so each later-read command
// composes on the right).
struct Affine {
  double l[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 t{0, 0, 0};

  Affine then_inner(const Affine& in) const {  // this o in
    Affine r;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        r.l[i][j] = 0;
        for (int k = 0; k < 3; ++k) r.l[i][j] += l[i][k] * in.l[k][j];
      }
      r.t[i] = t[i];
      for (int k = 0; k < 3; ++k) r.t[i] += l[i][k] * in.t[k];
    }
    return r;
  }
  Vec3 apply(const Vec3& p) const {
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = l[i][0] * p[0] + l[i][1] * p[1] + l[i][2] * p[2] + t[i];
    return r;
  }
  Vec3 apply_dir(const Vec3& p) const {
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = l[i][0] * p[0] + l[i][1] * p[1] + l[i][2] * p[2];
    return r;
  }
  Affine inverse() const {
    const double(&a)[3][3] = l;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    Affine r;
    r.l[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
    r.l[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    r.l[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    r.l[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
    r.l[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    r.l[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    r.l[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
    r.l[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    r.l[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    for (int i = 0; i < 3; ++i) r.t[i] = -(r.l[i][0] * t[0] + r.l[i][1] * t[1] + r.l[i][2] * t[2]);
    return r;
  }
  std::string mtx() const {
    std::string s = ":mtx";
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) s += " " + num(l[i][j]);
      s += " " + num(t[i]);
    }
    return s + " 0 0 0 1";
  }
};

// One move command as an affine map (right-handed rotations, line 8).
inline Affine move(const std::string& cmd, double v) {
  Affine a;
  const double pi = 3.14159265358979323846;
  const double c = std::cos(v * pi / 180), s = std::sin(v * pi / 180);
  if (cmd == ":mx") a.t[0] = v;
  if (cmd == ":my") a.t[1] = v;
  if (cmd == ":mz") a.t[2] = v;
  if (cmd == ":sx") a.l[0][0] = v;
  if (cmd == ":sy") a.l[1][1] = v;
  if (cmd == ":sz") a.l[2][2] = v;
  if (cmd == ":rx") { a.l[1][1] = c; a.l[1][2] = -s; a.l[2][1] = s; a.l[2][2] = c; }
  if (cmd == ":ry") { a.l[0][0] = c; a.l[0][2] = s; a.l[2][0] = -s; a.l[2][2] = c; }
  if (cmd == ":rz") { a.l[0][0] = c; a.l[0][1] = -s; a.l[1][0] = s; a.l[1][1] = c; }
  return a;
}

// A chain of moves written left to right, as one map.
struct Chain {
  std::vector<std::pair<std::string, double>> cmds;
  std::string text() const {
    std::string s;
    for (const auto& c : cmds) s += c.first + " " + num(c.second) + " ";
    return s;
  }
  Affine map() const {
    Affine a;
    for (const auto& c : cmds) a = a.then_inner(move(c.first, c.second));
    return a;
  }
};

// q(x) = x'Ax + b'x + c; inside where q < 0 (AMBIGUITIES E2).
struct Quadric {
  double a[3][3] = {};
  Vec3 b{0, 0, 0};
  double c = 0;

  double value(const Vec3& x) const {
    double v = c;
    for (int i = 0; i < 3; ++i) {
      v += b[i] * x[i];
      for (int j = 0; j < 3; ++j) v += a[i][j] * x[i] * x[j];
    }
    return v;
  }
  // The kind-0 coefficients a0..a9 of line 1059.
  std::string kind0() const {
    return num(a[0][0]) + " " + num(a[1][1]) + " " + num(a[2][2]) + " " + num(2 * a[0][1]) + " " +
           num(2 * a[1][2]) + " " + num(2 * a[0][2]) + " " + num(b[0]) + " " + num(b[1]) + " " + num(b[2]) +
           " " + num(c);
  }
  Quadric negated() const {
    Quadric q = *this;
    for (auto& row : q.a)
      for (double& v : row) v = -v;
    for (double& v : q.b) v = -v;
    q.c = -c;
    return q;
  }
  // The same solid after the map `m` (world = m(local)): q'(x) = q(m^-1 x).
  Quadric moved(const Affine& m) const {
    const Affine inv = m.inverse();
    Quadric r;
    // q(Lx + t) with L = inv.l, t = inv.t.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) s += inv.l[k][i] * a[k][l] * inv.l[l][j];
        r.a[i][j] = s;
      }
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) {
        double at = 0;
        for (int l = 0; l < 3; ++l) at += (a[k][l] + a[l][k]) * inv.t[l];
        s += (at + b[k]) * inv.l[k][j];
      }
      r.b[j] = s;
    }
    r.c = value(inv.t);
    return r;
  }
};

// alpha |w|^2 + beta (w.u)^2 + gamma with w = x - centre, u = axis / |axis|:
// every kind 2-8 is of this form (docs/eastray.md's table, in world terms).
inline Quadric axial(const Vec3& centre, const Vec3& axis, double alpha, double beta, double gamma) {
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const Vec3 u{axis[0] / n, axis[1] / n, axis[2] / n};
  Quadric q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) q.a[i][j] = (i == j ? alpha : 0.0) + beta * u[i] * u[j];
  // expand with x = w + centre: A(x - c) . (x - c)
  for (int i = 0; i < 3; ++i) {
    double s = 0;
    for (int j = 0; j < 3; ++j) s += q.a[i][j] * centre[j];
    q.b[i] = -2 * s;
  }
  double cc = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cc += q.a[i][j] * centre[i] * centre[j];
  q.c = cc + gamma;
  return q;
}

inline Quadric ellipsoid(const Vec3& c, double p, double q, double r) {
  Quadric e;
  e.a[0][0] = 1 / (p * p);
  e.a[1][1] = 1 / (q * q);
  e.a[2][2] = 1 / (r * r);
  for (int i = 0; i < 3; ++i) e.b[i] = -2 * c[i] * e.a[i][i];
  e.c = c[0] * c[0] * e.a[0][0] + c[1] * c[1] * e.a[1][1] + c[2] * c[2] * e.a[2][2] - 1;
  return e;
}

inline Quadric plane(const Vec3& p, const Vec3& n) {  // n.(x - p): outside on the normal's side
  Quadric q;
  q.b = n;
  q.c = -(n[0] * p[0] + n[1] * p[1] + n[2] * p[2]);
  return q;
}

inline std::string vec(const Vec3& v) { return num(v[0]) + " " + num(v[1]) + " " + num(v[2]); }

}  // namespace eprobe
