// Helpers for the host-send tests: running programs, files, temp dirs.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "sim_launcher.hpp"

namespace hs_test {

struct RunResult {
  int status = -1;  // exit status, or 128+signal
  std::string out, err;
};

// Runs argv[0] with the arguments; standard input from /dev/null.
RunResult run(const std::vector<std::string>& argv, int timeout_s = 300);

std::string read_file(const std::string& path);
// The board's in-memory texture preamble reader (textures::unpack) on
// `preamble` (from its marker) in a 1 MiB arena: its error, "" when it reads.
std::string unpack_textures_error(const std::string& preamble);
// A PNG texture of w x h: gradients (x times gx, y times gy) with noise
// from an LCG seeded with `seed`, shifted down by about noise_shift bits,
// so that it neither compresses to nothing nor is incompressible.
void write_texture(const std::string& path, int w, int h, std::uint32_t seed, int gx, int gy, int noise_shift);
bool file_exists(const std::string& path);
// A fresh directory under /tmp, removed by the destructor.
struct TempDir {
  TempDir();
  ~TempDir();
  std::string path;
  std::string file(const std::string& name) const { return path + "/" + name; }
};

// The exact bytes the firmware produces for `scene`, from the host renderer.
std::string reference_image(const std::string& scene, const std::string& size, const std::string& format);

// Starts the stand-in board on its own pty (path: board.pty_path()).
void start_standin(minrt::send::SimLauncher& board, const std::string& size, const std::string& format,
                   const std::string& protocol = "raw");

// The processes whose parent is `parent`, and whether `pid` still runs
// (a zombie does not), read from /proc.
std::vector<pid_t> children_of(pid_t parent);
bool alive(pid_t pid);

bool firmware_available();
// Ends the test case with a warning when firmware-sim or the firmware is
// not built (ctest then shows it passed vacuously, as for missing data).
#define HS_NEEDS_FIRMWARE()                                                                    \
  do {                                                                                         \
    if (!hs_test::firmware_available()) {                                                      \
      WARN("skipped: firmware-sim (" HS_FIRMWARE_SIM ") or firmware (" HS_FIRMWARE_ELF ") not built"); \
      return;                                                                                  \
    }                                                                                          \
  } while (0)
std::string shared_dir();
std::vector<std::string> bad_scenes();

// host-send against firmware-sim running the firmware: `extra` options,
// then `scene`, the image to `out`.
RunResult send_sim(const std::string& scene, const std::string& out, const std::vector<std::string>& extra);

// The options of the protocols other than raw that carry the text formats:
// course in either byte order, then framed.
const std::vector<std::vector<std::string>>& text_protocols();

// The words with a space between, for test messages.
std::string joined(const std::vector<std::string>& words);

// A scene whose board image is a PNG (CS418, miniRT, EASTRAY), in `dir`
// with `extra` options (a --size, say): every protocol of text_protocols()
// gives the raw protocol's PNG byte for byte, and its pixels are minrt's
// `--precision float --shims portable` image.
void check_png_on_every_protocol(const TempDir& dir, const std::string& scene, const std::vector<std::string>& extra);

}  // namespace hs_test
