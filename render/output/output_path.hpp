// The one resolver of output paths: links, standard streams, devices, folders and the run's own inputs.
#pragma once
#include <filesystem>
#include <string>

namespace vibra::render {

/// Where an output's bytes go, as resolve_output found them.
struct OutputTarget {
  std::string named;             ///< as the user gave it, for messages
  std::filesystem::path file;    ///< a file: where the bytes land (a symbolic link's final target), else empty
  bool stream = false;           ///< standard output, a pipe or a device: written as a stream, never renamed over
  std::filesystem::path device;  ///< a stream to a pipe or device opened by name; empty for a descriptor
  int descriptor = 1;            ///< a stream to a descriptor: 1 for "-" and /dev/stdout, N for /dev/fd/N

  /// For "wrote" lines: the name given, and the file it leads to when that is another.
  std::string shown() const;
};

/// What `refusal` says when a stream cannot take an output: any output that
/// needs a file (a page, a picture, an MP4, whose index goes at the start).
inline constexpr const char* kNeedsAFile = "this output needs a file: give a file name";

/// The one place an output path is read: every output goes through it
/// (videos, frame names, stills, pages and their companions, CSV, figures,
/// segments, concat), before any work and again when its file is made
/// (TemporaryFile). The rules (docs/reliability.md, "Output paths"):
/// - "" names nothing: refused.
/// - "-", /dev/stdout, /dev/fd/N, a FIFO, a character device or a socket is
///   a stream: the bytes go there as they come, nothing is renamed over it.
///   `no_stream` empty: allowed; else the output needs a file, and the
///   refusal ends with `no_stream` (what to do instead).
/// - A symbolic link is followed to its final target, which gets the output
///   (through a temporary beside it); the link stays. A loop is refused.
/// - A folder where a file is expected is refused, naming it.
/// - A file this run reads (core/input/input_files.hpp) is refused, naming both.
/// - Missing parent folders are allowed when they can be made (TemporaryFile
///   makes them, and removes them again if the output is not completed); a
///   file in the way or an unwritable folder is refused.
/// Throws OutputError with one line naming the path and the fix.
OutputTarget resolve_output(const std::string& named, const std::string& no_stream = kNeedsAFile);

/// The same rules for a file that vibra names for an output (a page's
/// companion, a segment, a frame, a temporary's final path): no stream.
/// Returns the file to write (a link's target).
std::filesystem::path resolve_output_file(const std::filesystem::path& path);

/// Throws OutputError naming both when `output` is a file this run reads.
void refuse_input_as_output(const std::filesystem::path& output);

/// The path's extension in lower case (".mp4"), or "": how every output's kind is told.
std::string lower_extension_of(const std::filesystem::path& path);

}  // namespace vibra::render
