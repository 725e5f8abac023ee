// The buffered stream --trace and --commit-log write to, with its first
// write error kept: a full disk or a reader that went away (EPIPE; SIGPIPE
// is ignored) stops the run with status 7 and a line naming the stream,
// instead of running on with a lost or truncated log.
#pragma once

#include <cstdio>
#include <string>

namespace fwsim {

class TraceStream {
 public:
  TraceStream() = default;
  ~TraceStream();
  TraceStream(const TraceStream&) = delete;
  TraceStream& operator=(const TraceStream&) = delete;

  // Takes `fd` (closed with the stream); `name` is what messages call it.
  // False with the reason when the stream cannot be made.
  bool open(int fd, const std::string& name, std::string& error);
  std::FILE* file() const { return file_; }
  // A write has failed (checked between slices of the run).
  bool failed() const { return err_ != 0 || (file_ != nullptr && std::ferror(file_)); }
  // Flushes and closes; false with "cannot write NAME: REASON" when any
  // write, the flush or the close failed.
  bool close(std::string& error);

 private:
  static ssize_t write_cookie(void* self, const char* buf, size_t n);
  std::FILE* file_ = nullptr;
  int fd_ = -1;
  int err_ = 0;  // errno of the first failed write
  std::string name_;
};

}  // namespace fwsim
