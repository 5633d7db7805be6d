// Checked writes to standard output: every byte vibra prints goes through here, failures reported once at exit.
#include "render/output/standard_output.hpp"

extern "C" {
#include <libavformat/avio.h>
#include <libavutil/error.h>
#include <libavutil/mem.h>
}

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdint>
#include <cstring>

#include "render/output/output_error.hpp"

namespace vibra::render {

namespace {
std::atomic<int> first_error = 0;

std::string& name() {
  static std::string text = "standard output";
  return text;
}

void record(int error) {
  int none = 0;
  first_error.compare_exchange_strong(none, error);
}

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
  if (error == 0) return size;
  record(error);
  return AVERROR(error);
}

/// errno after a failed stdio call (EIO should the library not have set it).
int stdio_error() { return errno != 0 ? errno : EIO; }
}  // namespace

void standard_output_failed(int error) {
  record(error);
  throw StandardOutputFailed{};
}

int standard_output_error() { return first_error.load(); }

const std::string& standard_output_name() { return name(); }

void send_standard_output_to(const OutputTarget& target) {
  if (!target.stream || (target.device.empty() && target.descriptor == STDOUT_FILENO)) return;
  std::fflush(stdout);
  int fd = target.descriptor;
  if (!target.device.empty()) {
    do fd = ::open(target.device.c_str(), O_WRONLY | O_CLOEXEC);
    while (fd < 0 && errno == EINTR);
  }
  if (fd < 0 || ::dup2(fd, STDOUT_FILENO) < 0)
    throw OutputError("cannot write to '" + target.named + "': " + std::strerror(errno) + ": choose another output");
  if (!target.device.empty()) ::close(fd);
  name() = target.named;
}

void print_standard_output(std::string_view text) {
  errno = 0;
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    standard_output_failed(stdio_error());
}

void write_standard_output(const void* data, std::size_t size) {
  if (const int error = write_all(static_cast<const std::uint8_t*>(data), size)) standard_output_failed(error);
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

void keep_standard_descriptors() {
  for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    const int opened = ::open("/dev/null", fd == STDIN_FILENO ? O_WRONLY : O_RDONLY);
    if (opened >= 0 && opened != fd) ::dup2(opened, fd), ::close(opened);
  }
}

int close_standard_output() {
  errno = 0;
  if (std::fflush(stdout) != 0)
    record(stdio_error());
  else if (std::ferror(stdout))
    record(EIO);  // a stdio write that was not checked where it was made
  // Closing the descriptor reports what a file system defers to close (NFS);
  // EBADF: it was never open, so nothing was written to it.
  if (::close(STDOUT_FILENO) != 0 && errno != EBADF && errno != EINTR) record(errno);
  return standard_output_error();
}

}  // namespace vibra::render
