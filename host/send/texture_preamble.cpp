#include "texture_preamble.hpp"

#include <zlib.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"
#include "core/base/inflate.hpp"
#include "protocol/texel_filter.hpp"

#include "eastray_maps.hpp"
#include "texture_files.hpp"

namespace minrt::send {

namespace {

using minrt::host::RgbTexture;
using minrt::host::TextureLoader;
using minrt::host::TextureProbe;

// The texels of one texture filtered (protocol/texel_filter.hpp) and
// deflated as a raw stream. False with zlib's reason.
bool deflate_texels(const RgbTexture& img, std::string& packed, std::string& error) {
  std::vector<std::uint8_t> residuals(img.rgb.size());
  texel_filter::filter(img.rgb.data(), static_cast<std::size_t>(img.width), static_cast<std::size_t>(img.height),
                       residuals.data());
  z_stream z{};
  // Raw deflate (negative window bits): the board checks the texels' own CRC-32.
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) {
    error = "zlib: cannot start the compressor";
    return false;
  }
  packed.resize(deflateBound(&z, residuals.size()));
  z.next_in = residuals.data();
  z.avail_in = static_cast<uInt>(residuals.size());
  z.next_out = reinterpret_cast<Bytef*>(packed.data());
  z.avail_out = static_cast<uInt>(packed.size());
  const int r = deflate(&z, Z_FINISH);
  packed.resize(z.total_out);
  deflateEnd(&z);
  if (r != Z_STREAM_END) {
    error = "zlib: compression did not finish";
    return false;
  }
  return true;
}

void put_le32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

// `where`: for each name, the "SCENE:LINE:COL: error: " its errors start
// with (empty: not located).
bool assemble(const std::vector<std::string>& names, const std::vector<std::string>& where,
              const std::string& base_dir, TextureProbe probe, TextureLoader load, std::uint64_t board_bytes,
              std::string& out, std::string& error) {
  out.clear();
  if (names.empty()) return true;
  if (names.size() > MINRT_MAX_TEXTURES) {
    error = "more than " + std::to_string(MINRT_MAX_TEXTURES) + " textures";
    return false;
  }
  // The headers' sizes first: a texture over the side limit, or the one
  // that takes the decoded textures over the board's memory, is refused
  // before any is decoded.
  std::uint64_t texel_bytes = 0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    if (name.size() > 255) {
      error = at + "texture name longer than 255 bytes";
      return false;
    }
    int width = 0, height = 0;
    if (!probe(base_dir, name, width, height, error)) {
      error = at + error;
      return false;
    }
    if (width > MINRT_MAX_TEXTURE_SIDE || height > MINRT_MAX_TEXTURE_SIDE) {
      error = at + "texture " + name + " is " + std::to_string(width) + "x" + std::to_string(height) +
              ", larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    texel_bytes += static_cast<std::uint64_t>(width) * height * 3;
    if (texel_bytes > board_bytes) {
      error = at + "texture " + name + " (" + std::to_string(width) + "x" + std::to_string(height) +
              ") takes the textures to " + std::to_string(texel_bytes) + " bytes decoded, over the " +
              std::to_string(board_bytes) +
              " bytes the board has for them (firmware-sim: --sim-ram-size to give the simulated board more)";
      return false;
    }
  }
  // Each texture's header, then its stream; `lead` is the most the texels
  // (counted from the first) run ahead of the bytes read (counted from the
  // marker) while the board's inflater decodes them in place.
  std::string body;
  std::uint64_t decoded = 0;
  long long lead = 0;
  const std::size_t header = 6;  // marker, count, lead
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    RgbTexture img;
    if (!load(base_dir, name, img, error)) {
      error = at + error;
      return false;
    }
    if (img.width > MINRT_MAX_TEXTURE_SIDE || img.height > MINRT_MAX_TEXTURE_SIDE) {
      error = at + "texture " + name + " is larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    std::string packed;
    if (!deflate_texels(img, packed, error)) {
      error = at + "texture " + name + ": " + error;
      return false;
    }
    body.push_back(static_cast<char>(name.size()));
    body += name;
    for (int v : {img.width, img.height}) {
      body.push_back(static_cast<char>(v & 0xff));
      body.push_back(static_cast<char>(v >> 8));
    }
    put_le32(body, static_cast<std::uint32_t>(packed.size()));
    put_le32(body, crc32(img.rgb.data(), img.rgb.size()));
    // The board's own inflater over the stream: the lead, and a check that
    // the stream gives back these texels' residuals.
    const std::size_t stream_at = header + body.size();
    std::vector<std::uint8_t> check(img.rgb.size());
    MemorySource src{reinterpret_cast<const std::uint8_t*>(packed.data()), packed.size()};
    Inflater inflater;
    if (inflater.run(src.source(), check.data(), check.size()) != InflateStatus::kDone ||
        inflater.produced() != check.size()) {
      error = at + "texture " + name + ": the compressed texels do not decode";
      return false;
    }
    lead = std::max(lead, static_cast<long long>(decoded) + inflater.lead() - static_cast<long long>(stream_at));
    decoded += img.rgb.size();
    body += packed;
  }
  out.push_back(static_cast<char>(MINRT_TEXTURES_DEFLATE_MARKER));
  out.push_back(static_cast<char>(names.size()));
  put_le32(out, static_cast<std::uint32_t>(lead));
  out += body;
  return true;
}

}  // namespace

bool build_texture_preamble(const std::string& scene, const std::string& scene_name, const std::string& base_dir,
                            std::uint64_t board_bytes, std::string& out, std::string& error) {
  std::vector<std::string> names;
  std::vector<std::string> where;  // each name's first use, as the reader counts lines and columns
  std::set<std::string> seen;
  std::istringstream lines(scene);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::string kw, name;
    if (!(words >> kw) || kw != "texture" || !(words >> name) || name == "none") continue;
    if (!seen.insert(name).second) continue;
    names.push_back(name);
    const std::size_t col = line.find(name, line.find("texture") + 7) + 1;
    where.push_back(scene_name + ":" + std::to_string(number) + ":" + std::to_string(col) + ": error: ");
  }
  return assemble(names, where, base_dir, &minrt::host::probe_png_texture, &minrt::host::load_png_texture, board_bytes, out, error);
}

bool build_minirt_texture_preamble(const std::string& scene, const std::string& scene_name,
                                   const std::string& base_dir, std::uint64_t board_bytes, std::string& out,
                                   std::string& error) {
  std::vector<std::string> names, where;
  std::set<std::string> seen;
  std::istringstream lines(scene);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (w.empty() || w[0] != "spt") continue;
    for (std::size_t i = 4; i < w.size() && i < 6; ++i) {  // texture, then the optional bump map
      if (!seen.insert(w[i]).second) continue;
      names.push_back(w[i]);
      // minrt's miniRT message for the same file: SCENE:LINE: FIELD "NAME": PATH: reason.
      where.push_back(scene_name + ":" + std::to_string(number) + ": textured sphere " +
                      (i == 4 ? "texture" : "bump map") + " \"" + w[i] + "\": ");
    }
  }
  return assemble(names, where, base_dir, &minrt::host::probe_minirt_texture, &minrt::host::load_minirt_texture, board_bytes, out, error);
}

bool build_eastray_texture_preamble(const std::vector<std::pair<std::string, std::string>>& maps,
                                    const std::string& base_dir, std::uint64_t board_bytes, std::string& out,
                                    std::string& error) {
  std::vector<std::string> names, where;
  std::set<std::string> seen;
  for (const auto& m : maps) {
    if (!seen.insert(m.first).second) continue;
    names.push_back(m.first);
    where.push_back(m.second);
  }
  return assemble(names, where, base_dir, &minrt::host::probe_eastray_map, &minrt::host::load_eastray_map, board_bytes, out,
                  error);
}

}  // namespace minrt::send
