// Roughness and the two-sided flip (SPEC.md 1.3, docs/cs418.md): the normal
// is perturbed first and the flip looks at the perturbed normal. On a plane
// seen at a grazing angle, lit from straight above, a perturbed normal that
// faces away from the viewer is turned round, away from the sun, and the
// pixel is black. Its probability has a closed form, so the count of black
// pixels is checked against it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "cs418_render.hpp"

TEST_CASE("roughness: a perturbed normal facing away from the viewer is flipped away from the light",
          "[cs418][roughness]") {
  const int w = 200, h = 100;
  const double sigma = 0.2;
  // Eye one unit above the plane y = 0, looking along the horizon; the sun
  // straight above. Nothing shadows the plane.
  const std::string scene = "png " + std::to_string(w) + " " + std::to_string(h) +
                            " h.png\neye 0 1 0\nsun 0 1 0\nroughness 0.2\nplane 0 1 0 0\n";
  minrt::host::DriverOptions o;
  o.threads = 2;
  minrt::host::RenderedScene r;
  std::string error;
  REQUIRE(minrt::test::render_cs418(scene, "h.txt", "", o, r, error));

  // Pixel (x, y) looks along d = (sx, sy, -1) / |.|. With n' = n + sigma g,
  // d.n' > 0 (flip) iff d.g > -d_y / sigma, and d.g ~ N(0, 1): the pixel is
  // black with probability Phi(d_y / sigma). (A normal left facing up is lit
  // unless g_y < -1/sigma = -5: negligible.)
  double expected = 0, variance = 0;
  int plane = 0, black = 0, hit = 0;
  const double m = w > h ? w : h;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double sx = (2.0 * x - w) / m, sy = (h - 2.0 * y) / m;
      const unsigned char* px = &r.image.rgba[4 * (static_cast<std::size_t>(y) * w + x)];
      if (px[3] != 0) ++hit;
      if (!(sy < 0)) continue;
      ++plane;
      const double dy = sy / std::sqrt(sx * sx + sy * sy + 1.0);
      const double p = 0.5 * std::erfc(-(dy / sigma) / std::sqrt(2.0));
      expected += p;
      variance += p * (1 - p);
      if (px[3] == 255 && px[0] == 0 && px[1] == 0 && px[2] == 0) ++black;
    }
  }
  CHECK(hit == plane);  // every ray below the horizon meets the plane, no other does
  INFO("black " << black << ", expected " << expected << " +- " << std::sqrt(variance));
  // Flipping before perturbing would leave almost every pixel lit (black ~ 0).
  CHECK(expected > 1000);
  CHECK(std::abs(black - expected) < 5 * std::sqrt(variance) + 1);
}
