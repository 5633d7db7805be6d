// vibra lecture --shots-dir: every shot as its own video and first-frame PNG, with index.md and a Beamer snippet.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "scenes/lecture/presented_shot.hpp"

namespace vibra::scenes {

/// Copies each shot's video and first frame into `staged` (the shots folder
/// being built) as NN-title.EXT and NN-title.png, and writes index.md (a table
/// of the shots, their lengths and endings) and beamer.tex (a frame a shot:
/// the video with its first frame as the poster). Throws OutputError.
void stage_shots_folder(const std::string& title, const std::string& storyboard,
                        const std::vector<PresentedShot>& shots, const std::filesystem::path& staged);

}  // namespace vibra::scenes
