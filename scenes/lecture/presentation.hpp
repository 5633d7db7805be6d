// vibra lecture --present: the presentation page's companion folder (a video and a first frame a shot) and its page.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/page/present_page.hpp"
#include "scenes/lecture/presented_shot.hpp"

namespace vibra::scenes {

/// Moves each shot's video and first frame into `staged` (the page's
/// companion folder being built, named `folder` beside the page) and
/// returns the page that shows them, one slide a shot. `whole` lists
/// further downloads already in the folder (the one-file video, its subtitles).
render::Presentation stage_presentation(const std::string& title, int width, int height, double fps,
                                        const std::vector<PresentedShot>& shots, const std::filesystem::path& staged,
                                        const std::string& folder, std::vector<render::PageDownload> whole);

}  // namespace vibra::scenes
