// vibra lecture --present: the presentation page's companion folder (a video and a first frame a shot) and its page.
#include "scenes/lecture/presentation.hpp"

#include "render/output/output_error.hpp"
#include "render/output/stop_signal.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {
/// Moves a finished file within the run's temporary folders (one file system).
void move_file(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) throw render::OutputError("cannot move '" + from.string() + "' to '" + to.string() + "': " + ec.message());
}

render::PresentSlide slide_of(const PresentedShot& shot, const std::string& video, const std::string& still) {
  render::PresentSlide slide;
  slide.title = shot.title;
  slide.video = video, slide.still = still;
  slide.frames = shot.frames;
  slide.then = shot_end_word(shot.ending.then);
  slide.intro = shot.ending.intro;
  slide.notes = shot.notes;
  slide.interval = shot.interval;
  slide.time_map = shot.time_map;
  slide.sound = shot.sound;
  return slide;
}
}  // namespace

render::Presentation stage_presentation(const std::string& title, int width, int height, double fps,
                                        const std::vector<PresentedShot>& shots, const fs::path& staged,
                                        const std::string& folder, std::vector<render::PageDownload> whole) {
  render::Presentation page;
  page.title = title;
  page.width = width + (width & 1), page.height = height + (height & 1);  // videos are even-sized
  page.fps = fps;
  for (const PresentedShot& shot : shots) {
    render::throw_if_stop_requested();
    const std::string stem = shot_file_stem(shot, shots.size());
    const std::string video = stem + shot.video.extension().string(), still = stem + ".png";
    move_file(shot.video, staged / video);
    move_file(shot.still, staged / still);
    page.slides.push_back(slide_of(shot, folder + video, folder + still));
  }
  page.downloads = std::move(whole);
  return page;
}

}  // namespace vibra::scenes
