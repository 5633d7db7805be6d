// How a path appears in what vibra records of a run (a page's "Made by", a video's comment, a subtitle file's note): relative to where it ran, never the folders above.
#pragma once
#include <string>

namespace vibra {

/// `path` as a record of the run shows it:
///  - a relative path, or a device (/dev/..., /proc/...): as given;
///  - an absolute path that shares a folder with the working directory:
///    relative to it ("story.toml", "../story.toml");
///  - any other absolute path: its file name alone.
std::string shown_path(const std::string& path);

/// A command-line argument with the path it is, or holds after its first
/// '=' (--set road=/data/road.csv, --output=/tmp/x.mp4), shown by shown_path.
std::string shown_argument(const std::string& argument);

}  // namespace vibra
