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

// `bytes` deflated as a raw stream. False with zlib's reason.
bool deflate_bytes(const std::vector<std::uint8_t>& bytes, std::string& packed, std::string& error,
                   int level = Z_BEST_COMPRESSION) {
  z_stream z{};
  // Raw deflate (negative window bits): the board checks the texels' own CRC-32.
  if (deflateInit2(&z, level, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) {
    error = "zlib: cannot start the compressor";
    return false;
  }
  packed.resize(deflateBound(&z, bytes.size()));
  z.next_in = const_cast<Bytef*>(bytes.data());
  z.avail_in = static_cast<uInt>(bytes.size());
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

// The texels of one texture filtered (protocol/texel_filter.hpp) and deflated.
bool deflate_texels(const RgbTexture& img, std::string& packed, std::string& error,
                    int level = Z_BEST_COMPRESSION) {
  std::vector<std::uint8_t> residuals(img.rgb.size());
  texel_filter::filter(img.rgb.data(), static_cast<std::size_t>(img.width), static_cast<std::size_t>(img.height),
                       residuals.data());
  return deflate_bytes(residuals, packed, error, level);
}

// One texture's sparse form (include/minrt/serial_protocol.h): the tiles
// of 2^(form-1) texels a side that hold a texel read, their texels
// deflated behind the tile mask, and the CRC-32 of the texture as the
// board will hold it.
struct SparseForm {
  int form = 0;
  std::uint32_t sent = 0;
  std::uint32_t crc = 0;
  std::string packed;
};

// The smallest sparse form of `img` for the texels `read` marks; false
// when none is smaller than the whole form would decode to.
bool best_sparse_form(const RgbTexture& img, const std::vector<std::uint8_t>& read, SparseForm& best,
                      std::string& error) {
  const std::size_t w = static_cast<std::size_t>(img.width), h = static_cast<std::size_t>(img.height);
  bool found = false;
  std::vector<std::uint8_t> best_stream;
  // Tiles of 1 to 16 texels a side: small tiles send fewer texels, large
  // ones a smaller mask and better predictions.
  for (int shift = 0; shift <= 4 && shift < MINRT_TEXTURES_MAX_TILE_FORM; ++shift) {
    const std::size_t tx = tiles_along(w, shift);
    const std::size_t mask = tile_mask_bytes(w, h, shift);
    std::vector<std::uint8_t> stream(mask, 0);
    for (std::size_t y = 0; y < h; ++y)
      for (std::size_t x = 0; x < w; ++x)
        if (read[y * w + x] != 0) {
          const std::size_t t = (y >> shift) * tx + (x >> shift);
          stream[t >> 3] = static_cast<std::uint8_t>(stream[t >> 3] | 1u << (t & 7));
        }
    const TileMask m{stream.data(), tx, shift};
    const std::size_t sent = texel_filter::sent_texels(m, w, h);
    if (mask + 3 * sent > img.rgb.size()) continue;  // no room for it in the texture's own bytes
    std::vector<std::uint8_t> view = img.rgb;
    for (std::size_t y = 0; y < h; ++y)
      for (std::size_t x = 0; x < w; ++x)
        if (!m.has(x, y))
          for (int c = 0; c < 3; ++c) view[(y * w + x) * 3 + c] = texel_filter::kUnsent[c];
    stream.resize(mask + 3 * sent);
    texel_filter::filter_sparse(view.data(), w, h, TileMask{stream.data(), tx, shift}, stream.data() + mask);
    SparseForm f;
    f.form = shift + 1;
    f.sent = static_cast<std::uint32_t>(sent);
    f.crc = crc32(view.data(), view.size());
    // Ranked by a fast deflate; only the winner is deflated hard.
    if (!deflate_bytes(stream, f.packed, error, Z_BEST_SPEED)) return false;
    if (!found || f.packed.size() < best.packed.size()) {
      best = std::move(f);
      best_stream = std::move(stream);
    }
    found = true;
  }
  return found && deflate_bytes(best_stream, best.packed, error);
}

void put_le32(std::string& out, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

// One texture ready for the line: its name, size, whole form (and the
// lead its in-place decoding needs) and, when it has one, its sparse form.
struct Packed {
  std::string name;
  int width = 0, height = 0;
  std::string whole;
  std::uint32_t crc = 0;
  long long lead = 0;  // how far the board's inflater ran ahead of the stream's start
  bool sparse = false;
  SparseForm part;
};

// `where`: for each name, the "SCENE:LINE:COL: error: " its errors start
// with (empty: not located). `marks`: the texels the render reads, by name
// (null: send every texel).
bool assemble(const std::vector<std::string>& names, const std::vector<std::string>& where,
              const std::string& base_dir, TextureProbe probe, TextureLoader load, std::uint64_t board_bytes,
              const TexelMarks* marks, std::string& out, std::string& error, TexelCount* count = nullptr) {
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
  std::vector<Packed> packed(names.size());
  std::vector<RgbTexture> images(names.size());
  // The whole form, deflated hard, and the lead its in-place decoding
  // needs, found by running the board's own inflater over it (which also
  // checks that the stream gives back these texels' residuals).
  auto pack_whole = [&](std::size_t k) {
    Packed& p = packed[k];
    const RgbTexture& img = images[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    if (!deflate_texels(img, p.whole, error)) {
      error = at + "texture " + p.name + ": " + error;
      return false;
    }
    std::vector<std::uint8_t> check(img.rgb.size());
    MemorySource src{reinterpret_cast<const std::uint8_t*>(p.whole.data()), p.whole.size()};
    Inflater inflater;
    if (inflater.run(src.source(), check.data(), check.size()) != InflateStatus::kDone ||
        inflater.produced() != check.size()) {
      error = at + "texture " + p.name + ": the compressed texels do not decode";
      return false;
    }
    p.lead = inflater.lead();
    return true;
  };
  bool any_sparse = false;
  for (std::size_t k = 0; k < names.size(); ++k) {
    Packed& p = packed[k];
    p.name = names[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    RgbTexture& img = images[k];
    if (!load(base_dir, p.name, img, error)) {
      error = at + error;
      return false;
    }
    if (img.width > MINRT_MAX_TEXTURE_SIDE || img.height > MINRT_MAX_TEXTURE_SIDE) {
      error = at + "texture " + p.name + " is larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    p.width = img.width;
    p.height = img.height;
    p.crc = crc32(img.rgb.data(), img.rgb.size());
    const auto read = marks != nullptr ? marks->find(p.name) : TexelMarks::const_iterator{};
    if (marks != nullptr && read != marks->end() && read->second.size() == img.rgb.size() / 3) {
      std::string why;
      if (!best_sparse_form(img, read->second, p.part, why)) {
        if (!why.empty()) {
          error = at + "texture " + p.name + ": " + why;
          return false;
        }
      } else {
        // Against the whole form deflated fast (about a tenth of the
        // time of the hard one, a few percent larger): the hard one is
        // made only when it may be sent.
        std::string quick;
        if (!deflate_texels(img, quick, error, Z_BEST_SPEED)) {
          error = at + "texture " + p.name + ": " + error;
          return false;
        }
        p.sparse = p.part.packed.size() < quick.size();
        any_sparse = any_sparse || p.sparse;
      }
    }
    if (!p.sparse && !pack_whole(k)) return false;
  }
  // Sparse textures are decoded into the arena beside the held upload, not
  // in place: when both do not fit, every texel goes.
  std::uint64_t sparse_upload = 0;
  for (const Packed& p : packed) sparse_upload += 32 + p.name.size() + (p.sparse ? p.part.packed.size() : p.whole.size());
  if (any_sparse && texel_bytes + sparse_upload > board_bytes) {
    any_sparse = false;
    for (std::size_t k = 0; k < packed.size(); ++k)
      if (packed[k].sparse && !pack_whole(k)) return false;
  }
  const int marker = any_sparse ? MINRT_TEXTURES_SPARSE_MARKER : MINRT_TEXTURES_DEFLATE_MARKER;
  // Each texture's header, then its stream; `lead` is the most the texels
  // (counted from the first) run ahead of the bytes read (counted from the
  // marker) while the board's inflater decodes them in place.
  std::string body;
  std::uint64_t decoded = 0;
  long long lead = 0;
  const std::size_t header = 6;  // marker, count, lead
  for (const Packed& p : packed) {
    const bool part = any_sparse && p.sparse;
    const std::string& stream = part ? p.part.packed : p.whole;
    body.push_back(static_cast<char>(p.name.size()));
    body += p.name;
    for (int v : {p.width, p.height}) {
      body.push_back(static_cast<char>(v & 0xff));
      body.push_back(static_cast<char>(v >> 8));
    }
    put_le32(body, static_cast<std::uint32_t>(stream.size()));
    put_le32(body, part ? p.part.crc : p.crc);
    if (any_sparse) {
      body.push_back(static_cast<char>(part ? p.part.form : 0));
      put_le32(body, part ? p.part.sent : static_cast<std::uint32_t>(p.width) * static_cast<std::uint32_t>(p.height));
    }
    const std::size_t stream_at = header + body.size();
    lead = std::max(lead, static_cast<long long>(decoded) + p.lead - static_cast<long long>(stream_at));
    decoded += static_cast<std::uint64_t>(p.width) * p.height * 3;
    body += stream;
    if (count != nullptr) {
      count->texels += static_cast<std::uint64_t>(p.width) * p.height;
      count->sent += part ? p.part.sent : static_cast<std::uint64_t>(p.width) * p.height;
    }
  }
  out.push_back(static_cast<char>(marker));
  out.push_back(static_cast<char>(names.size()));
  put_le32(out, any_sparse ? 0u : static_cast<std::uint32_t>(lead));
  out += body;
  return true;
}

}  // namespace

bool build_texture_preamble(const std::string& scene, const std::string& scene_name, const std::string& base_dir,
                            std::uint64_t board_bytes, std::string& out, std::string& error, const TexelMarks* marks,
                            TexelCount* sent) {
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
  return assemble(names, where, base_dir, &minrt::host::probe_png_texture, &minrt::host::load_png_texture, board_bytes,
                  marks, out, error, sent);
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
  return assemble(names, where, base_dir, &minrt::host::probe_minirt_texture, &minrt::host::load_minirt_texture, board_bytes,
                  nullptr, out, error);
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
  return assemble(names, where, base_dir, &minrt::host::probe_eastray_map, &minrt::host::load_eastray_map, board_bytes,
                  nullptr, out, error);
}

}  // namespace minrt::send
