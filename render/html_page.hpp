#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vibra::render {

/// Facts about a render shown under the video or player: (name, value).
using PageFacts = std::vector<std::pair<std::string, std::string>>;

/// An HTML5 page with a video tag whose sources are listed in order (MP4
/// first: Safari needs H.264; then WebM for Chrome, Firefox, Opera).
std::string video_page_html(const std::string& title, const std::vector<std::string>& sources, int width, int height,
                            const PageFacts& facts);

/// The classic frame player: steps through PNG frames `prefix` + zero-padded
/// index (`digits` wide) + ".png", with play/pause, step, and a speed control.
std::string frames_player_html(const std::string& title, const std::string& prefix, int digits, long long frames,
                               double fps, int width, int height, const PageFacts& facts);

/// Writes text to `path` through a temporary file (nothing partial is left).
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// Escapes &, <, >, " for HTML text and attributes.
std::string html_escape(const std::string&);

}  // namespace vibra::render
