#pragma once
#include <cstddef>

struct AVIOContext;

namespace vibra::render {

/// The reader of standard output has gone (`vibra render -o - | head -c 1000`,
/// or a player that was closed). Not a failure: the run ends quietly with
/// exit code 0, as a pipeline expects, like `vibra ascii | head`.
struct StreamClosed {};

/// Writes all of `size` bytes to standard output, retrying short writes.
/// Throws StreamClosed when the reader has gone (EPIPE; SIGPIPE is ignored),
/// OutputError for any other failure (`> /dev/full`: disk full).
void write_standard_output(const void* data, std::size_t size);

/// An FFmpeg I/O context that writes through write_standard_output's checks:
/// a failed write sets the context's error to AVERROR(errno) (EPIPE for a
/// gone reader), which the muxer returns. Free with close_standard_output_io.
AVIOContext* open_standard_output_io();
/// Flushes and frees the context; returns the first write error, or 0.
int close_standard_output_io(AVIOContext*&);

}  // namespace vibra::render
