// Part of the min-rt tracer (render/sld/tracer.hpp).
// Rows in bands: render_rows gives any band of rows the bytes of the
// whole-image render, so that workers can render bands of one image in
// parallel, each with a tracer of its own.
//
// The original reuses its three pixel lines without clearing them. A trace
// whose energy falls to 0.1 or below after a mirror ends without marking
// the next slot unused, so the diffuse pass then reads what earlier rows
// left in the later slots of that pixel (ss20 and tsu3 depend on it). A
// tracer that skips the rows other workers render therefore keeps, for each
// slot, the row as of which it holds the one-thread contents (slot_rows_).
// Only when a trace ends early over a slot that is behind does
// resolve_slots look for the latest row that wrote it, tracing that pixel's
// eye ray in the skipped rows (geometry only, newest first). Rows two bands
// both need are traced once and handed over (SharedRows).
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::prepare_bands(Arena& arena) -> bool {
  slot_rows_ = arena.alloc_zeroed<int16_t>(3 * static_cast<size_t>(width_) * kMaxDepth);
  if (slot_rows_ == nullptr) return false;
  // Line l holds the rows r with (r + 1) % 3 == l, the first being
  // (l + 2) % 3; before it the line holds init's zeros, as in the original.
  for (int l = 0; l < 3; ++l) {
    const auto before = static_cast<int16_t>((l + 2) % 3 - 3);
    int16_t* rows = slot_rows_ + l * width_ * kMaxDepth;
    for (int i = 0; i < width_ * kMaxDepth; ++i) rows[i] = before;
  }
  return true;
}

// Row r lives in line (r + 1) % 3 and samples from group 2r mod 5 onwards,
// as in the original's loop. Row y is scanned with rows y - 1 and y + 1, so
// a band needs rows y0 - 1 to y1 traced in full; rows y0 - 1, y0 and y1 - 1,
// y1 are shared with the neighbouring bands.
template <MathPolicy M>
inline auto Tracer<M>::render_rows(int y0, int y1, const RowSink& out, const SharedRows& shared) -> void {
  auto group = [](int r) { return 2 * r % 5; };
  const int first = y0 > 0 ? y0 - 1 : 0;
  if (slot_rows_ == nullptr) {
    // No slot rows: the rows above the band are replayed, geometry only.
    for (int r = lines_through_ + 1; r < first; ++r) pretrace_line<false>(line_of(r), r, group(r));
  }
  if (first > lines_through_ + 1) lines_through_ = first - 1;
  const bool sharing = shared.take != nullptr && slot_rows_ != nullptr;
  const size_t pixel_bytes = sizeof(Pixel) * static_cast<size_t>(width_);
  const size_t slot_bytes = sizeof(int16_t) * static_cast<size_t>(width_) * kMaxDepth;
  auto trace = [&](int r) {
    const bool across = sharing && ((y0 > 0 && r <= y0) || (y1 < height_ && r >= y1 - 1));
    if (!across || !shared.take(shared.ctx, r, line_of(r), pixel_bytes, slot_rows_of(r, 0), slot_bytes)) {
      pretrace_line<true>(line_of(r), r, group(r));
      if (across) shared.give(shared.ctx, r, line_of(r), pixel_bytes, slot_rows_of(r, 0), slot_bytes);
    }
    lines_through_ = r;
  };
  for (int r = lines_through_ + 1; r <= y0; ++r) trace(r);
  for (int y = y0; y < y1; ++y) {
    const int r = y + 1;
    if (r < height_ && r > lines_through_) trace(r);
    scan_pixels(y, line_of(y - 1), line_of(y), line_of(y + 1));
    out.row(y, row_);
  }
}

// A slot written by the trace of row y holds row y's contents. One it did
// not write still does if it held row y - 3's, the line's previous row.
template <MathPolicy M>
inline auto Tracer<M>::track_slots(Pixel& pixel, int x, int y, int written) -> void {
  int16_t* rows = slot_rows_of(y, x);
  for (int n = 0; n < kMaxDepth; ++n)
    if (n < written || rows[n] == y - 3) rows[n] = static_cast<int16_t>(y);
  // Ended early (a surface in the last slot written): the diffuse pass
  // reads on into the slots earlier rows left.
  if (written < kMaxDepth && pixel.surface_ids[written - 1] >= 0) resolve_slots(pixel, rows, x, y, written);
}

// Brings slots n.. of `pixel` up to row y while they hold surfaces (the
// diffuse pass stops at the first -1). A trace writes a prefix of the
// slots, so the latest row to write slot n + 1 is never newer than the one
// that wrote slot n: one walk up the line's rows serves them all.
template <MathPolicy M>
inline auto Tracer<M>::resolve_slots(Pixel& pixel, int16_t* rows, int x, int y, int n) -> void {
  Pixel older;  // row q's geometry at this pixel
  int q = y - 3, traced = -1, written = 0;
  while (n < kMaxDepth) {
    if (q > rows[n]) {  // rows q and above may have written slot n since
      if (traced != q) {
        R row[3], dir[3];
        eye_row(q, row);
        eye_ray(row, x, dir);
        copy3(startp_, viewpoint_);
        written = trace_ray<false>(0, R(1.0), dir, older);
        traced = q;
      }
      if (n >= written) {
        q -= 3;
        continue;
      }
      // What trace_ray writes into a slot.
      pixel.surface_ids[n] = older.surface_ids[n];
      if (older.surface_ids[n] >= 0) {
        copy3(pixel.points[n], older.points[n]);
        pixel.calc_diffuse[n] = older.calc_diffuse[n];
        if (older.calc_diffuse[n]) {
          copy3(pixel.energy[n], older.energy[n]);
          copy3(pixel.normals[n], older.normals[n]);
        }
      }
    }
    rows[n] = static_cast<int16_t>(y);
    if (pixel.surface_ids[n] < 0) return;
    ++n;
  }
}

}  // namespace minrt
