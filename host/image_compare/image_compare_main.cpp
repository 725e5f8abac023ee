// image-compare: how far apart two images are, with the measures of
// SPEC.md 1.6 (premultiplied RGBA). Reads PNG, PPM and BMP.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image_load.hpp"
#include "image_metrics.hpp"
#include "posix/output_file.hpp"

namespace {

void print_help(std::FILE* f) {
  std::fputs(
      "Usage: image-compare [OPTIONS] A B\n"
      "Compares two images of the same size (PNG, PPM or BMP, found by content) on\n"
      "premultiplied RGBA and prints: pixels off by more than 1 in any channel, alpha\n"
      "mismatches, the largest channel error, the PSNR of block-averaged colour, the\n"
      "mean difference per channel (A - B) and the coverage (pixels with alpha > 0).\n"
      "\n"
      "  --block N         block size for the PSNR (default 4; 16 from 800 pixels wide)\n"
      "  --max-off N       exit 1 when more than N pixels are off by more than 1\n"
      "  --identical       exit 1 unless every decoded RGBA byte is equal\n"
      "  --sheet OUT.png   also write a contact sheet: A | B | difference (pixels off\n"
      "                    by more than 1 in red, smaller differences amplified 16x);\n"
      "                    transparency shows as a checkerboard\n"
      "  -h, --help        this text\n"
      "  --version         version\n"
      "Exit status: 0 compared (and within --max-off, identical with --identical),\n"
      "1 over --max-off or not identical, 2 bad usage\n"
      "or unreadable image.\n",
      f);
}

[[noreturn]] void usage(const std::string& msg) {
  std::fprintf(stderr, "image-compare: error: %s (see image-compare --help)\n", msg.c_str());
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  const char* paths[2] = {nullptr, nullptr};
  int n = 0;
  int block = 0;
  long max_off = -1;
  const char* sheet = nullptr;
  bool identical = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      print_help(stdout);
      return 0;
    } else if (arg == "--version") {
      std::printf("image-compare %s\n", MINRT_VERSION);
      return 0;
    } else if (arg == "--block" || arg == "--max-off") {
      if (i + 1 >= argc) usage(arg + " needs a value");
      char* end = nullptr;
      const long v = std::strtol(argv[++i], &end, 10);
      if (*end != 0 || v < 0 || v > 1000000000L || (arg == "--block" && v < 1)) usage("bad value for " + arg);
      if (arg == "--block") block = static_cast<int>(v);
      else max_off = v;
    } else if (arg == "--identical") {
      identical = true;
    } else if (arg == "--sheet") {
      if (i + 1 >= argc) usage("--sheet needs a value");
      sheet = argv[++i];
    } else if (!arg.empty() && arg[0] == '-') {
      usage("unknown option '" + arg + "'");
    } else if (n == 2) {
      usage("more than two images given");
    } else {
      paths[n++] = argv[i];
    }
  }
  if (n != 2) usage("two images are needed");
  // The sheet's path is checked before the images are read and compared.
  if (sheet != nullptr) {
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
      std::fprintf(stderr, "image-compare: error: %s: %s\n", paths[k], why.c_str());
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
  if (sheet != nullptr) {
    const minrt::host::RgbaImage out = minrt::host::contact_sheet(img[0], img[1]);
    minrt::host::AtomicOutput file(minrt::host::Durability::kSynced);
    std::string why;
    if (!file.open(sheet, false, why) || !minrt::host::write_png(file.file(), out, why) || !file.commit(why)) {
      std::fprintf(stderr, "image-compare: error: %s: %s\n", sheet, why.c_str());
      return 2;
    }
  }
  if (identical && img[0].rgba != img[1].rgba) {
    std::fprintf(stderr, "image-compare: the images differ\n");
    return 1;
  }
  return max_off >= 0 && d.off_by_more_than_1 > max_off ? 1 : 0;
}
