// Checked writes to standard output: every byte vibra prints goes through here, failures reported once at exit.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

#include "render/output/output_path.hpp"

struct AVIOContext;

namespace vibra::render {

// Every byte vibra writes to standard output goes through this file, and
// every write is checked. A failed write records its errno (the first one
// counts) and the command stops; main's check at exit (close_standard_output)
// then reports it as one line, `vibra: error: writing standard output: ...`,
// with exit code 2, or ends quietly for EPIPE: the reader has gone
// (`vibra solve ... | head`; SIGPIPE is ignored), a pipeline's normal end.

/// Thrown to stop a command whose standard output failed, after the error was
/// recorded. main catches it and leaves the message to the check at exit.
struct StandardOutputFailed {};

/// Records `error` (an errno) as standard output's failure and throws
/// StandardOutputFailed.
[[noreturn]] void standard_output_failed(int error);

/// Writes `text` through stdio's stdout and flushes it (each call reaches the
/// reader at once: a terminal sees whole lines).
void print_standard_output(std::string_view text);

/// Writes all of `size` bytes to descriptor 1 directly, retrying short writes
/// (raw video frames: no copy through stdio). Do not mix with
/// print_standard_output in one command.
void write_standard_output(const void* data, std::size_t size);

/// An FFmpeg I/O context that writes through write_standard_output's checks:
/// a failed write is recorded and sets the context's error to AVERROR(errno),
/// which the muxer returns. Free with close_standard_output_io.
AVIOContext* open_standard_output_io();
/// Flushes and frees the context; returns the first write error, or 0.
int close_standard_output_io(AVIOContext*&);

/// Makes a stream output (resolve_output: a pipe or device by name, or a
/// descriptor such as /dev/fd/2) this process's standard output, so it is
/// written as `-o -` is, every write checked; messages then name it. A FIFO
/// opens when a reader has opened it. Nothing to do for standard output
/// itself. Throws OutputError when it cannot be opened.
void send_standard_output_to(const OutputTarget&);

/// "standard output", or the pipe or device it was sent to.
const std::string& standard_output_name();

/// The errno of standard output's first failed write, or 0.
int standard_output_error();

/// At start: a closed descriptor 0, 1 or 2 is opened on /dev/null for the
/// other direction, so no file vibra opens can take its number and writes to
/// a closed standard output still fail (EBADF), as gnulib's stdopen does.
void keep_standard_descriptors();

/// The check at exit (coreutils' close_stdout): flushes stdout and closes
/// descriptor 1; returns the errno of the first failure (recorded, or met
/// now), or 0.
int close_standard_output();

}  // namespace vibra::render
