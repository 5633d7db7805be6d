// classify_output: what kind of output a -o name is, decided in one place for every command.
#pragma once
#include <string>

#include "render/output/output_path.hpp"  // lower_extension_of, for the callers of classify_output

namespace vibra::render {

/// The kinds of output vibra writes.
enum class OutputKind {
  stream,   ///< "-": standard output (a pipe or device named as a file is told by resolve_output)
  page,     ///< PAGE.html and its PAGE_files/
  video,    ///< a file of a container kContainers names (.mp4, .webm, ...)
  frames,   ///< a frame pattern (frames/tmp_%04d.png) or a directory
  picture,  ///< one picture: .png, .svg or .pdf
  unknown,  ///< none of these: each command says what it takes
};

/// What `-o name` names, by its name alone (and whether it is a folder),
/// in that order: "-", .html, a video extension, a pattern or folder, a
/// picture extension.
OutputKind classify_output(const std::string& name);

}  // namespace vibra::render
