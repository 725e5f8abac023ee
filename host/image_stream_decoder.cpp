#include "image_stream_decoder.hpp"

#include "image_window.hpp"

namespace minrt::host {

namespace {

constexpr int kMaxSide = 1 << 16;  // larger sides are not followed (the file is still shown whole)

uint32_t le32(const uint8_t* p) {
  return p[0] | (uint32_t{p[1]} << 8) | (uint32_t{p[2]} << 16) | (uint32_t{p[3]} << 24);
}
uint32_t be32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}
bool is_space(uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// PNG's Paeth predictor.
uint8_t paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = p > a ? p - a : a - p, pb = p > b ? p - b : b - p, pc = p > c ? p - c : c - p;
  return static_cast<uint8_t>(pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
}

}  // namespace

void ImageStreamDecoder::feed(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size && state_ != State::kGaveUp && state_ != State::kDone; ++i) step(data[i]);
}

void ImageStreamDecoder::start_image(int width, int height) {
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide) return give_up();
  if (window_.width() == 0) window_.begin(width, height);
  if (window_.width() != width || window_.height() != height) return give_up();
  width_ = width;
  height_ = height;
  row_.assign(static_cast<size_t>(width) * 3, 0);
  at_ = 0;
  row_index_ = 0;
}

void ImageStreamDecoder::row_done(int file_row) {
  const int y = kind_ == Kind::kBmp && bottom_up_ ? height_ - 1 - file_row : file_row;
  window_.row_rgb(y, row_.data());
  at_ = 0;
  if (++row_index_ == height_) state_ = State::kDone;
}

void ImageStreamDecoder::step(uint8_t c) {
  switch (state_) {
    case State::kMagic:
      magic_.push_back(static_cast<char>(c));
      if (magic_ == "P3" || magic_ == "P6") {
        kind_ = Kind::kPpm;
        p3_ = magic_ == "P3";
        state_ = State::kPpmHeader;
      } else if (magic_ == "BM") {
        kind_ = Kind::kBmp;
        header_[0] = 'B';
        header_[1] = 'M';
        header_at_ = 2;
        state_ = State::kBmpHeader;
      } else if (magic_.size() == 8) {
        if (magic_ != std::string("\x89PNG\r\n\x1a\n", 8)) return give_up();
        kind_ = Kind::kPng;
        state_ = State::kPng;
      } else if (magic_.size() >= 2 && magic_[0] != '\x89') {
        return give_up();
      }
      return;
    case State::kPpmHeader: return ppm_header_byte(c);
    case State::kPpmPixels: return ppm_pixel_byte(c);
    case State::kBmpHeader:
    case State::kBmpPixels: return bmp_byte(c);
    case State::kPng: return png_byte(c);
    case State::kGaveUp:
    case State::kDone: return;
  }
}

// ---- PPM ----

void ImageStreamDecoder::ppm_header_byte(uint8_t c) {
  if (in_comment_) {
    in_comment_ = c != '\n' && c != '\r';
    return;
  }
  if (c == '#' && !in_token_) {
    in_comment_ = true;
    return;
  }
  if (c >= '0' && c <= '9') {
    if (!in_token_) fields_[field_] = 0;
    in_token_ = true;
    if (fields_[field_] > 100000000) return give_up();
    fields_[field_] = fields_[field_] * 10 + (c - '0');
    return;
  }
  if (!is_space(c) || !in_token_) {
    if (!is_space(c)) give_up();
    return;
  }
  in_token_ = false;
  if (++field_ < 3) return;
  if (fields_[2] < 1 || fields_[2] > 65535) return give_up();
  bytes_per_sample_ = fields_[2] > 255 ? 2 : 1;
  start_image(static_cast<int>(fields_[0]), static_cast<int>(fields_[1]));
  if (state_ != State::kGaveUp) state_ = State::kPpmPixels;
}

void ImageStreamDecoder::ppm_pixel_byte(uint8_t c) {
  long v;
  if (p3_) {
    if (in_comment_) {
      in_comment_ = c != '\n' && c != '\r';
      return;
    }
    if (c >= '0' && c <= '9') {
      value_ = (value_ < 0 ? 0 : value_ * 10) + (c - '0');
      if (value_ > 65535) return give_up();
      return;
    }
    if (c == '#' && value_ < 0) {
      in_comment_ = true;
      return;
    }
    if (!is_space(c)) return give_up();
    if (value_ < 0) return;
    v = value_;
    value_ = -1;
  } else if (bytes_per_sample_ == 2) {
    if (value_ < 0) {
      value_ = c;
      return;
    }
    v = (value_ << 8) | c;
    value_ = -1;
  } else {
    v = c;
  }
  const long maxval = fields_[2];
  if (v > maxval) v = maxval;
  row_[at_++] = static_cast<uint8_t>(maxval == 255 ? v : (v * 255 + maxval / 2) / maxval);
  if (at_ == row_.size()) row_done(row_index_);
}

// ---- BMP ----

void ImageStreamDecoder::bmp_byte(uint8_t c) {
  if (state_ == State::kBmpHeader) {
    if (header_at_ < sizeof header_) header_[header_at_] = c;
    ++header_at_;
    if (header_at_ == 14) {
      data_offset_ = le32(header_ + 10);
      if (data_offset_ < 54 || data_offset_ > sizeof header_) return give_up();
    }
    if (header_at_ < 14 || header_at_ < data_offset_) return;
    const int32_t w = static_cast<int32_t>(le32(header_ + 18));
    const int32_t h = static_cast<int32_t>(le32(header_ + 22));
    const int bits = header_[28] | (header_[29] << 8);
    const uint32_t compression = le32(header_ + 30);
    if ((bits != 24 && bits != 32) || compression != 0 || h == 0 || h == INT32_MIN) return give_up();
    bottom_up_ = h > 0;
    bmp_bytes_per_pixel_ = bits / 8;
    bmp_stride_ = (static_cast<size_t>(w) * bits + 31) / 32 * 4;
    start_image(w, bottom_up_ ? h : -h);
    if (state_ == State::kGaveUp) return;
    state_ = State::kBmpPixels;
    return;
  }
  // at_ counts the bytes of the file row; pixels land in row_ as RGB.
  const size_t x = at_ / bmp_bytes_per_pixel_, channel = at_ % bmp_bytes_per_pixel_;
  if (x < static_cast<size_t>(width_) && channel < 3) row_[3 * x + (2 - channel)] = c;
  if (++at_ == bmp_stride_) row_done(row_index_);
}

// ---- PNG ----

void ImageStreamDecoder::png_byte(uint8_t c) {
  if (chunk_at_ < 8) {
    chunk_head_[chunk_at_++] = c;
    if (chunk_at_ == 8) chunk_length_ = be32(chunk_head_);
    if (chunk_at_ == 8 && chunk_length_ > (1u << 31)) give_up();
    return;
  }
  const size_t in_data = chunk_at_ - 8;
  ++chunk_at_;
  const bool ihdr = chunk_head_[4] == 'I' && chunk_head_[5] == 'H' && chunk_head_[6] == 'D' && chunk_head_[7] == 'R';
  const bool idat = chunk_head_[4] == 'I' && chunk_head_[5] == 'D' && chunk_head_[6] == 'A' && chunk_head_[7] == 'T';
  if (in_data < chunk_length_) {
    if (ihdr && in_data < 13) {
      header_[in_data] = c;
      if (in_data == 12) {
        const uint32_t w = be32(header_), h = be32(header_ + 4);
        const int depth = header_[8], colour = header_[9], interlace = header_[12];
        if (depth != 8 || (colour != 2 && colour != 6) || interlace != 0) return give_up();
        png_channels_ = colour == 6 ? 4 : 3;
        start_image(static_cast<int>(w > kMaxSide ? 0 : w), static_cast<int>(h > kMaxSide ? 0 : h));
        if (state_ == State::kGaveUp) return;
        row_.assign(1 + static_cast<size_t>(width_) * png_channels_, 0);
        previous_.assign(row_.size(), 0);
      }
    } else if (idat) {
      if (width_ == 0) return give_up();  // pixels before the header
      png_idat_byte(c);
    }
    return;
  }
  if (chunk_at_ == 12 + static_cast<size_t>(chunk_length_)) chunk_at_ = 0;  // after the CRC
}

void ImageStreamDecoder::png_idat_byte(uint8_t c) {
  if (zlib_header_ < 2) {
    if (zlib_header_ == 0 && (c & 0x0f) != 8) return give_up();  // not deflate
    ++zlib_header_;
    return;
  }
  if (block_left_ == 0 && block_head_ < 5) {
    if (last_block_) return;  // the Adler-32 checksum
    block_bytes_[block_head_++] = c;
    if (block_head_ == 1 && ((c >> 1) & 3) != 0) return give_up();  // a compressed block: not followed
    if (block_head_ < 5) return;
    last_block_ = (block_bytes_[0] & 1) != 0;
    block_left_ = block_bytes_[1] | (uint32_t{block_bytes_[2]} << 8);
    block_head_ = 0;
    return;
  }
  --block_left_;
  png_inflated_byte(c);
}

void ImageStreamDecoder::png_inflated_byte(uint8_t c) {
  row_[at_++] = c;
  if (at_ < row_.size()) return;
  // Unfilter (filter type, then the bytes) against the previous row.
  const int bpp = png_channels_;
  uint8_t* r = row_.data() + 1;
  const uint8_t* p = previous_.data() + 1;
  const size_t n = row_.size() - 1;
  const uint8_t filter = row_[0];
  for (size_t i = 0; i < n; ++i) {
    const int a = i >= static_cast<size_t>(bpp) ? r[i - bpp] : 0;
    const int b = p[i];
    const int cc = i >= static_cast<size_t>(bpp) ? p[i - bpp] : 0;
    switch (filter) {
      case 0: break;
      case 1: r[i] = static_cast<uint8_t>(r[i] + a); break;
      case 2: r[i] = static_cast<uint8_t>(r[i] + b); break;
      case 3: r[i] = static_cast<uint8_t>(r[i] + ((a + b) >> 1)); break;
      case 4: r[i] = static_cast<uint8_t>(r[i] + paeth(a, b, cc)); break;
      default: return give_up();
    }
  }
  previous_.swap(row_);
  row_.assign(previous_.size(), 0);
  at_ = 0;
  if (png_channels_ == 4) window_.row_rgba(row_index_, previous_.data() + 1);
  else window_.row_rgb(row_index_, previous_.data() + 1);
  if (++row_index_ == height_) state_ = State::kDone;
}

}  // namespace minrt::host
