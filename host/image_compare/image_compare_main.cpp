// image-compare: how far apart two images are, with the measures of
// SPEC.md 1.6 (premultiplied RGBA). Reads PNG, PPM and BMP.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image_load.hpp"
#include "image_metrics.hpp"
#include "posix/command_line.hpp"
#include "posix/output_file.hpp"

namespace {

const minrt::cli::Tool& tool() {
  static const minrt::cli::Tool t{
      "image-compare",
      R"(Usage: image-compare [OPTIONS] A B
Compares two images of the same size (PNG, PPM or BMP, found by content) on
premultiplied RGBA and prints: pixels off by more than 1 in any channel, alpha
mismatches, the largest channel error, the PSNR of block-averaged colour, the
mean difference per channel (A - B) and the coverage (pixels with alpha > 0).

)",
      {
          {"block", 0, "N", "block size for the PSNR (default 4; 16 from 800 pixels wide)"},
          {"max-off", 0, "N", "exit 1 when more than N pixels are off by more than 1"},
          {"identical", 0, nullptr, "exit 1 unless every decoded RGBA byte is equal"},
          {"sheet", 0, "OUT.png",
           "also write a contact sheet: A | B | difference (pixels off\n"
           "by more than 1 in red, smaller differences amplified 16x);\n"
           "transparency shows as a checkerboard"},
      },
      "Exit status: 0 compared (and within --max-off, identical with --identical),\n"
      "1 over --max-off or not identical, 2 bad usage or unreadable image.\n",
      2,
      2,
      "image"};
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  int block = 0;
  long max_off = -1;
  std::string sheet;
  bool identical = false;
  int status = 0;
  const bool go_on = minrt::cli::parse_tool(
      argc, argv, tool(), MINRT_VERSION,
      [&](const minrt::cli::Option* o, const std::string& v) -> std::string {
        const std::string name = o->name;
        if (name == "identical") identical = true;
        else if (name == "sheet") sheet = v;
        else if (name == "block" || name == "max-off") {
          char* end = nullptr;
          const long n = std::strtol(v.c_str(), &end, 10);
          if (v.empty() || *end != 0 || n < 0 || n > 1000000000L || (name == "block" && n < 1))
            return "bad value for --" + name;
          if (name == "block") block = static_cast<int>(n);
          else max_off = n;
        }
        return "";
      },
      status, &paths);
  if (!go_on) return status;
  // The sheet's path is checked before the images are read and compared.
  if (!sheet.empty()) {
    std::string why;
    if (!minrt::host::check_output_target(sheet, false, why)) {
      std::fprintf(stderr, "image-compare: error: %s\n", why.c_str());
      return 2;
    }
  }
  minrt::host::RgbaImage img[2];
  for (int k = 0; k < 2; ++k) {
    std::string why;
    if (!minrt::host::load_image(paths[k], img[k], why)) {
      std::fprintf(stderr, "image-compare: error: %s: %s\n", paths[k].c_str(), why.c_str());
      return 2;
    }
  }
  if (img[0].width != img[1].width || img[0].height != img[1].height) {
    std::fprintf(stderr, "image-compare: error: sizes differ: %dx%d and %dx%d\n", img[0].width, img[0].height,
                 img[1].width, img[1].height);
    return 2;
  }
  const minrt::host::ImageDiff d = minrt::host::compare_images(img[0], img[1], block);
  std::printf("pixels           %ld (%dx%d)\n", d.pixels, img[0].width, img[0].height);
  std::printf("off by > 1       %ld (%.3f%%)\n", d.off_by_more_than_1, 100.0 * d.off_by_more_than_1 / d.pixels);
  std::printf("alpha mismatches %ld\n", d.alpha_mismatch);
  std::printf("max channel err  %.2f\n", d.max_channel_error);
  if (std::isinf(d.block_psnr)) std::printf("block PSNR       inf (identical %dx%d blocks)\n", d.block, d.block);
  else std::printf("block PSNR       %.2f dB (%dx%d blocks)\n", d.block_psnr, d.block, d.block);
  std::printf("mean diff A-B    %.3f %.3f %.3f\n", d.mean_diff[0], d.mean_diff[1], d.mean_diff[2]);
  std::printf("coverage         %ld %ld\n", d.coverage_a, d.coverage_b);
  if (!sheet.empty()) {
    const minrt::host::RgbaImage out = minrt::host::contact_sheet(img[0], img[1]);
    minrt::host::AtomicOutput file(minrt::host::Durability::kSynced);
    std::string why;
    if (!file.open(sheet, false, why) || !minrt::host::write_png(file.file(), out, why) || !file.commit(why)) {
      std::fprintf(stderr, "image-compare: error: %s: %s\n", sheet.c_str(), why.c_str());
      return 2;
    }
  }
  if (identical && img[0].rgba != img[1].rgba) {
    std::fprintf(stderr, "image-compare: the images differ\n");
    return 1;
  }
  return max_off >= 0 && d.off_by_more_than_1 > max_off ? 1 : 0;
}
