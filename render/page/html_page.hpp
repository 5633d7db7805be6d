// The lecture page: one HTML file with the run's video or frames, its plots, facts and player.
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/page/page_plots.hpp"

namespace vibra::render {

/// Facts about a run shown in the page's table: (name, value), each name once.
using PageFacts = std::vector<std::pair<std::string, std::string>>;

/// What a page shows above its plots, and how media time maps to the run's.
struct PageMedia {
  enum class Kind { none, video, frames };
  Kind kind = Kind::none;
  std::vector<std::string> videos;  ///< files relative to the page, in source order (MP4 first: Safari needs H.264)
  std::string frames_prefix;        ///< frames: name prefix relative to the page ("x_frames/frame_")
  int digits = 4;                   ///< frames: zero-padded index width
  int width = 0, height = 0;
  long long frames = 0;
  double fps = 30;
  double frame_interval = 0;  ///< simulated time from one frame to the next
  /// Slow motion and pauses: from `video` seconds on, simulated time runs at
  /// `rate` per second of video from `simulated`. Empty: frame k shows
  /// k * frame_interval. The page maps the video's time through the same
  /// pieces as the render (scenes/timing/time_map.hpp).
  struct TimePiece {
    double video = 0, simulated = 0, rate = 0;
  };
  std::vector<TimePiece> time_map;
  /// Subtitles (WebVTT) relative to the page, shown by the video ("": none).
  std::string subtitles;
  /// The video speaks (a narrated lecture): played with its sound and controls, not muted and looped.
  bool sound = false;
};

/// A chapter of a lecture page's video: its title and where it starts.
struct PageChapter {
  std::string title;
  double start = 0;  ///< seconds of video
};

/// A file offered for download, relative to the page.
struct PageDownload {
  std::string label, file;
};

/// A lecture page: the media, the run's time series as interactive plots
/// (uPlot, compiled in: the page needs no network), its facts, the command
/// that made it and its downloads.
struct LecturePage {
  std::string title;
  PageMedia media;
  std::vector<PagePanel> panels;
  PageFacts facts;
  std::string command_line;
  std::vector<PageDownload> downloads;
  /// A lecture's shots, listed under the video; a click seeks to one.
  std::vector<PageChapter> chapters;
};

/// The page as one self-contained HTML file (template render/page/lecture.html.in).
std::string lecture_page_html(const LecturePage&);

class TemporaryFile;

/// Writes text into `file`'s temporary; commit() puts it in place.
void write_text(const TemporaryFile& file, const std::string& text);

/// Writes text to `path` through a temporary file (nothing partial is left).
void write_text_file(const std::filesystem::path& path, const std::string& text);

/// A whole text file, as written; OutputError when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace vibra::render
