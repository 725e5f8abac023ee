#include "stdio_stream.hpp"

namespace minrt::host {

void FileSink::write_fn(void* ctx, const uint8_t* data, size_t size) {
  auto* self = static_cast<FileSink*>(ctx);
  if (!self->failed && std::fwrite(data, 1, size, self->file) != size) self->failed = true;
}

}  // namespace minrt::host
