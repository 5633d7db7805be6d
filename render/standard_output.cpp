#include "render/standard_output.hpp"

extern "C" {
#include <libavformat/avio.h>
#include <libavutil/error.h>
#include <libavutil/mem.h>
}

#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>

#include "render/output_error.hpp"

namespace vibra::render {

namespace {
/// Writes everything; returns 0 or the errno of the failed write.
int write_all(const std::uint8_t* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(STDOUT_FILENO, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += n, size -= static_cast<std::size_t>(n);
  }
  return 0;
}

int write_packet(void*, std::uint8_t* data, int size) {
  const int error = write_all(data, static_cast<std::size_t>(size));
  return error == 0 ? size : AVERROR(error);
}
}  // namespace

void write_standard_output(const void* data, std::size_t size) {
  const int error = write_all(static_cast<const std::uint8_t*>(data), size);
  if (error == EPIPE) throw StreamClosed{};
  if (error != 0)
    throw OutputError(std::string("writing to standard output failed: ") + std::strerror(error) +
                      ": send it to a pipe or a file with room");
}

AVIOContext* open_standard_output_io() {
  constexpr int kBufferSize = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(av_malloc(kBufferSize));
  if (!buffer) return nullptr;
  AVIOContext* io = avio_alloc_context(buffer, kBufferSize, 1, nullptr, nullptr, write_packet, nullptr);
  if (!io) av_free(buffer);
  return io;
}

int close_standard_output_io(AVIOContext*& io) {
  if (!io) return 0;
  avio_flush(io);
  const int error = io->error;
  av_freep(&io->buffer);
  avio_context_free(&io);
  return error;
}

}  // namespace vibra::render
