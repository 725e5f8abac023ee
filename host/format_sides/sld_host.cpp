// SLD on the host: the original min-rt's bytes, streamed as the band
// renderer finishes rows (render_variants.cpp), to standard output or -o.
#include "sld_host.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "image_stream_decoder.hpp"
#include "image_window.hpp"
#include "posix/progress_line.hpp"
#include "render_driver.hpp"
#include "stdio_stream.hpp"

namespace minrt::host {

int stream_sld(const SceneInput& in, const DriverOptions& options, const WarningSink& warnings) {
  RenderOptions render;
  const formats::Format& f = formats::format_of(formats::FormatId::kSld);
  render.width = options.width > 0 ? options.width : f.default_width;
  render.height = options.height > 0 ? options.height : f.default_height;
  render.format = options.p6 ? PpmFormat::kP6 : PpmFormat::kP3;

  // With -o the image goes to a unique temporary file renamed into place
  // only once it is complete (posix/output_file.hpp).
  AtomicOutput output(options.durability);
  std::FILE* out = stdout;
  const bool to_file = !options.output_path.empty() && options.output_path != "-";
  if (to_file) {
    std::string why;
    if (!output.open(options.output_path, options.write_through, why)) {
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitSceneError;
    }
    out = output.file();
  }

  MemorySource source{reinterpret_cast<const uint8_t*>(in.text.data()), in.text.size()};
  FileSink file_sink{out};
  // --show: the PPM bytes also go through a decoder that hands each row to
  // the window as soon as it is written.
  LiveWindow window;
  if (options.show) {
    std::string why;
    if (!window.open("minrt: " + in.shown, why))
      std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  }
  ImageStreamDecoder decoder(window);
  struct Tee {
    ByteSink file;
    ImageStreamDecoder* decoder;
    static void write_fn(void* ctx, const uint8_t* data, size_t size) {
      auto* t = static_cast<Tee*>(ctx);
      t->file.put(data, size);
      t->decoder->feed(data, size);
    }
  } tee{file_sink.sink(), &decoder};
  const ByteSink sink = window.is_open() ? ByteSink{&Tee::write_fn, &tee} : file_sink.sink();
  // Several threads hand the PPM writer each row once the rows above it are
  // done: the window takes them as they finish instead (a row given twice
  // keeps its first).
  struct WindowRows {
    LiveWindow* window;
    void begin(int, int) {}
    void row(int y, const uint8_t* rgb) { window->row_rgb(y, rgb); }
    void end() {}
  } window_rows{&window};
  window.begin(render.width, render.height);
  const RowSink to_window = row_sink_of(window_rows);
  // The progress line counts the rows as they go to the writer, in order;
  // never between the image's bytes on a terminal.
  WorkProgress progress(options.progress && (to_file || ::isatty(STDOUT_FILENO) == 0), "minrt: rendering", "rows",
                        static_cast<std::uint64_t>(render.height), kProgressAfterSeconds);
  PpmWriter ppm(sink, render.format);
  struct CountedRows {
    RowSink out;
    WorkProgress* progress;
    void begin(int w, int h) { out.begin(w, h); }
    void row(int y, const uint8_t* rgb) {
      out.row(y, rgb);
      progress->add();
    }
    void end() { out.end(); }
  } counted{ppm.sink(), &progress};
  Diagnostic error;
  const RenderStatus st = render_variant_rows(options.variant, source.source(), row_sink_of(counted), render, error,
                                              warnings, options.threads, window.is_open() ? &to_window : nullptr);
  progress.finish();
  const bool write_failed = file_sink.failed || std::fflush(out) != 0;
  if (st != RenderStatus::kOk) {
    output.discard();
    if (error.has_pos)
      std::fprintf(stderr, "%s:%d:%d: error: %s\n", in.shown.c_str(), error.pos.line, error.pos.col, error.message);
    else
      std::fprintf(stderr, "%s: error: %s\n", in.shown.c_str(), error.message);
    return st == RenderStatus::kSceneError ? kExitSceneError : kExitIoError;
  }
  if (write_failed) {
    output.discard();
    std::fprintf(stderr, "minrt: error: write error on the image\n");
    return kExitIoError;
  }
  if (to_file) {
    std::string why;
    if (!output.commit(why)) {
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitIoError;
    }
  }
  std::string why;
  if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return 0;
}

}  // namespace minrt::host
