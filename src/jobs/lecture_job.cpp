// The lecture job: a storyboard's shots rendered into one video with chapters and subtitles.
#include "jobs/lecture_job.hpp"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "core/input/input_files.hpp"
#include "scenes/overlays/note_room.hpp"
#include "core/input/quoted_value.hpp"
#include "core/input/shown_path.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/text.hpp"
#include "render/encode/join/clip_join.hpp"
#include "render/encode/first_frame_sink.hpp"
#include "render/encode/subtitle_cue.hpp"
#include "render/encode/join/video_concat.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/place_together.hpp"
#include "render/output/progress.hpp"
#include "render/output/stop_signal.hpp"
#include "render/output/temporary_file.hpp"
#include "render/encode/output_kind.hpp"
#include "render/page/html_page.hpp"
#include "render/typeset/formula_text.hpp"
#include "scenes/lecture/narration.hpp"
#include "scenes/lecture/presentation.hpp"
#include "scenes/lecture/shots_folder.hpp"
#include "scenes/lecture/storyboard.hpp"
#include "scenes/lecture/title_card.hpp"
#include "scenes/overlays/note.hpp"
#include "jobs/render_job.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/timing/time_map.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {
/// A shot made ready to render: its scene with the speed its seconds ask
/// for, its frames, and its subtitles in seconds from the shot's start.
struct PlannedShot {
  const Shot* shot = nullptr;
  SceneConfig scene;
  long long frames = 0;
  std::vector<render::SubtitleCue> cues;
  std::string tag;  ///< the shot file's description: which lecture shot, which render
  std::vector<double> spoken_at;    ///< its spoken notes' video times, from the shot's start
  std::vector<SpokenPiece> speech;  ///< what it says, when
  double interval = 0;  ///< a scene's simulated time from frame to frame (0: a card)
  std::vector<render::PageMedia::TimePiece> time_map;  ///< a scene's pacing, as a page shows its clock
};

/// FNV-1a of what shapes a shot's frames and coding, so that a shot file of
/// another storyboard, shot or video setting is never taken for this one.
std::string shot_tag(const Storyboard& board, const Shot& shot, const render::VideoSettings& video) {
  std::string text = std::to_string(board.width) + "x" + std::to_string(board.height) + "@" +
                     std::to_string(board.fps) + "\n" + board.title + "\n" + shot.source + "\n" + video.codec + "\n" +
                     video.quality + "\n" + std::to_string(video.crf) + "\n" + video.preset;
  std::error_code ec;
  if (!shot.is_card && fs::is_regular_file(shot.scene.name + ".toml", ec)) text += render::read_text_file(shot.scene.name + ".toml");
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : text) hash = (hash ^ byte) * 1099511628211ull;
  char out[80];
  std::snprintf(out, sizeof out, "vibra lecture shot %d: render %016llx", shot.number,
                static_cast<unsigned long long>(hash));
  return out;
}

PlannedShot plan_card(const Storyboard& board, const Shot& shot) {
  PlannedShot p;
  p.shot = &shot;
  p.frames = std::max(1LL, std::llround(*shot.seconds * board.fps));
  std::string text = render::rich_text_plain(shot.card);
  const std::string equation = render::formula_plain_text(shot.equation);
  if (!equation.empty()) text += (text.empty() ? "" : "\n") + equation;
  p.cues.push_back({0, double(p.frames) / board.fps, text});
  return p;
}

/// The speed that makes a shot of `seconds` exactly round(seconds * fps)
/// frames: frame k shows video time k / fps, so the run's end T is shown by
/// the last frame, at (frames - 1) / fps.
double speed_for_seconds(const SceneConfig& scene, double T, double seconds) {
  const long long frames = std::llround(seconds * scene.fps);
  if (frames < 2)
    throw UsageError("seconds = " + short_number(seconds) + " is less than two frames at " + short_number(scene.fps) +
                     " fps: a scene shot needs its start and its end, so give seconds >= " +
                     short_number(2 / scene.fps));
  const double last_frame = double(frames - 1) / scene.fps;
  double held = 0;
  for (const Pause& p : scene.pacing.pauses) held += p.seconds;
  if (!(last_frame > held))
    throw UsageError("seconds = " + short_number(seconds) + " leaves no time for the motion: the pauses alone take " +
                     short_number(held) + " s of the " + short_number(last_frame) +
                     " s before the last frame, so give more seconds or shorter pauses");
  return scene.pacing.rate_for_length(T, last_frame);
}

/// Whether some frame of `clock` shows `note` (the scene draws it as a callout then).
bool note_on_screen(const Note& note, const FrameClock& clock) {
  const long long k = clock.first_frame_from(note.from);
  return k < clock.frames() && note.shown_at(clock.time(k));
}

/// Subtitles for the notes no frame shows (a note at an instant between two
/// frames): a note is shown once, in the picture or as a subtitle, never both.
/// Each lasts at least kShortestNoteCue, up to the next cue or the shot's end.
std::vector<render::SubtitleCue> note_cues(const std::vector<Note>& notes, const FrameClock& clock,
                                           const TimeMap& map, double length) {
  constexpr double kShortestNoteCue = 2;  // seconds: time to read a line
  std::vector<render::SubtitleCue> cues;
  for (const Note& note : notes) {
    if (note_on_screen(note, clock)) continue;
    const double start = map.first_video_time(note.from);
    const double end = std::max(map.first_video_time(note.to), start + kShortestNoteCue);
    cues.push_back({start, std::min(length, end), render::rich_text_plain(note.text)});
  }
  std::sort(cues.begin(), cues.end(), [](const auto& a, const auto& b) { return a.start < b.start; });
  for (std::size_t i = 0; i + 1 < cues.size(); ++i) cues[i].end = std::min(cues[i].end, cues[i + 1].start);
  return cues;  // MP4's subtitles cannot overlap
}

PlannedShot plan_scene(const Storyboard& board, const Shot& shot) {
  PlannedShot p;
  p.shot = &shot;
  p.scene = shot.scene;
  const TimeMesh mesh = build_scene_runs(p.scene)->info().mesh;  // reads the run's files (a road)
  if (!std::isfinite(mesh.T)) throw UsageError("a shot needs a finite end time: give T or periods");
  if (shot.seconds) p.scene.speed = speed_for_seconds(p.scene, mesh.T, *shot.seconds);
  const FrameClock clock = frame_clock_of(p.scene, mesh);
  p.frames = clock.frames();
  const double end_time = p.scene.frame_per_step ? double(mesh.steps) * mesh.dt : mesh.T;
  const TimeMap map(end_time, video_rate_of(p.scene, mesh), p.scene.pacing);
  std::vector<Note> notes;
  for (const std::string& spec : p.scene.notes) {
    notes.push_back(parse_note(spec));
    if (notes.back().to > end_time * (1 + 1e-12)) {
      char text[160];
      std::snprintf(text, sizeof text, "note %g-%g reaches past the run's end T = %g: end it at most there",
                    notes.back().from, notes.back().to, end_time);
      throw UsageError(text);
    }
  }
  refuse_crowded_notes(notes, p.scene.width, p.scene.height);
  for (const SpokenNote& spoken : shot.speech.notes) p.spoken_at.push_back(map.first_video_time(spoken.at));
  p.cues = note_cues(notes, clock, map, double(p.frames) / board.fps);
  p.interval = clock.interval();
  if (clock.time_map()) {  // the pieces, then the run's last time, held (as a render's page has them)
    for (const TimePiece& piece : clock.time_map()->pieces()) p.time_map.push_back({piece.video, piece.simulated, piece.rate});
    p.time_map.push_back({clock.time_map()->duration(), clock.time_map()->end(), 0});
  }
  ShotEnding ending = shot.ending;  // an intro against the frames the pacing made
  const std::string problem = settle_ending(ending, double(p.frames) / board.fps);
  if (!problem.empty()) throw UsageError("intro " + problem);
  return p;
}

/// A shot's speech placed, and its words as its subtitles: a card that
/// speaks shows its words rather than its text.
void add_speech(const Storyboard& board, PlannedShot& p, const ShotNarration& narration) {
  p.speech = shot_pieces(board, *p.shot, narration, p.spoken_at, double(p.frames) / board.fps);
  if (p.speech.empty()) return;
  if (p.shot->is_card && !p.shot->speech.say.empty()) p.cues.clear();
  for (const render::SubtitleCue& c : speech_cues(p.speech)) p.cues.push_back(c);
  std::stable_sort(p.cues.begin(), p.cues.end(), [](const auto& a, const auto& b) { return a.start < b.start; });
  for (std::size_t i = 0; i + 1 < p.cues.size(); ++i) p.cues[i].end = std::min(p.cues[i].end, p.cues[i + 1].start);
}

/// Every shot planned, or the first problem as one line naming the file and shot.
std::vector<PlannedShot> plan_lecture(const Storyboard& board, const render::VideoSettings& video,
                                      const std::vector<ShotNarration>& narration) {
  std::vector<PlannedShot> plan;
  for (const Shot& shot : board.shots) {
    try {
      plan.push_back(shot.is_card ? plan_card(board, shot) : plan_scene(board, shot));
      add_speech(board, plan.back(), narration[plan.size() - 1]);
    } catch (const UsageError& e) {
      const std::string message = e.what();
      if (message.rfind(board.file, 0) == 0) throw;
      throw UsageError(board.file + ": shot " + std::to_string(shot.number) + ": " + message);
    }
    plan.back().tag = shot_tag(board, shot, video);
  }
  return plan;
}

/// The chosen shots' sound, one after the other; none when none speaks.
std::optional<render::AudioClip> sound_of(const std::vector<const PlannedShot*>& shots, double fps) {
  std::vector<const std::vector<SpokenPiece>*> pieces;
  std::vector<double> starts;
  long long frame = 0;
  bool speaks = false;
  for (const PlannedShot* p : shots) {
    pieces.push_back(&p->speech);
    starts.push_back(double(frame) / fps);
    frame += p->frames;
    speaks = speaks || !p->speech.empty();
  }
  if (!speaks) return std::nullopt;
  return lecture_sound(pieces, starts, double(frame) / fps);
}

/// --script: the narration to record from, on standard output.
void write_script(const Storyboard& board, const std::vector<PlannedShot>& plan) {
  std::vector<double> seconds;
  for (const PlannedShot& p : plan) seconds.push_back(double(p.frames) / board.fps);
  const std::string script = narration_script(board, seconds);
  if (std::fwrite(script.data(), 1, script.size(), stdout) != script.size() || std::fflush(stdout) != 0)
    throw render::OutputError("writing the script to standard output failed: " + std::string(std::strerror(errno)));
}

/// The text of a container's "description" ("" when unreadable): a shot file's tag.
std::string description_of(const fs::path& video) { return render::read_video_description(video); }

/// "lecture.mp4" -> "lecture.shot-02.mp4" (the number padded to the shot count's width).
fs::path shot_file(const std::string& output, int number, std::size_t shots) {
  const fs::path out(output);
  const int width = int(std::to_string(shots).size());
  char digits[16];
  std::snprintf(digits, sizeof digits, "%0*d", width, number);
  return out.parent_path() / (out.stem().string() + ".shot-" + digits + out.extension().string());
}

/// One sink for `files` (one, or MP4 and WebM for a page), `frames` long,
/// tagged `tag` (a shot file's, "" for none); its notes are told once.
std::unique_ptr<render::FrameSink> sink_for(const Storyboard& board, const std::vector<fs::path>& files,
                                            long long frames, const LectureRequest& r, const std::string& tag) {
  std::map<std::string, std::string> metadata;
  if (!tag.empty()) metadata["description"] = tag;
  std::vector<std::string> outputs;
  for (const fs::path& file : files) outputs.push_back(file.string());
  std::unique_ptr<render::FrameSink> sink =
      render::make_frame_sinks(outputs, board.width, board.height, board.fps, frames, r.video, metadata);
  if (!r.quiet)
    for (const std::string& note : sink->notes()) std::fprintf(stderr, "vibra: %s\n", note.c_str());
  return sink;
}

/// Draws a card once and encodes it `p.frames` times into `sink`.
void render_card(const Storyboard& board, const PlannedShot& p, render::FrameSink& sink, const std::string& label,
                 bool quiet) {
  render::Canvas canvas = render::Canvas::image(board.width, board.height);
  draw_title_card(canvas, {board.title, p.shot->card, p.shot->equation});
  canvas.flush();
  render::Progress progress(label, p.frames, quiet);
  const render::Damage unchanged(board.width, board.height);
  for (long long k = 0; k < p.frames; ++k) {
    render::throw_if_stop_requested();
    sink.write(canvas.data(), canvas.stride(), k == 0 ? nullptr : &unchanged);  // the same picture again
    progress.update(k + 1);
  }
  progress.finish(p.frames);
}

/// "shot 2/4 Drag takes energy out": what the progress bar calls a shot.
std::string shot_label(const Storyboard& board, const PlannedShot& p) {
  return "shot " + std::to_string(p.shot->number) + "/" + std::to_string(board.shots.size()) + " " +
         one_line_message(p.shot->title, 40);
}

/// What render is asked for a scene shot played into `sink`; `output` names the kind of video.
RenderRequest shot_request(const Storyboard& board, const PlannedShot& p, render::FrameSink& sink,
                           const fs::path& output, const LectureRequest& r) {
  RenderRequest request;
  request.scene = p.scene;
  request.output = output.string();
  request.video = r.video;
  request.quiet = r.quiet;
  request.progress_label = shot_label(board, p);
  request.report_written = false;
  request.command_line = r.command_line;
  request.into = &sink;
  return request;
}

/// Renders one shot into `sink`, left open, starting on a keyframe (so that
/// its chapter starts cleanly when shots share the sink); `output` names the
/// kind of video. A scene shot made ready before (`prepared`) is played as it is.
void render_shot_into(const Storyboard& board, const PlannedShot& p, render::FrameSink& sink, const fs::path& output,
                      const LectureRequest& r, std::unique_ptr<PreparedRender> prepared = nullptr) {
  sink.start_keyframe();
  if (p.shot->is_card) return render_card(board, p, sink, shot_label(board, p), r.quiet);
  if (!prepared) prepared = std::make_unique<PreparedRender>(shot_request(board, p, sink, output, r));
  prepared->play();
}

/// Renders one shot into `files` of its own, tagged as the shot's.
void render_shot(const Storyboard& board, const PlannedShot& p, const std::vector<fs::path>& files,
                 const LectureRequest& r) {
  const std::unique_ptr<render::FrameSink> sink = sink_for(board, files, p.frames, r, p.tag);
  render_shot_into(board, p, *sink, files.front(), r);
  sink->finish();
}

/// The subtitles file beside a video may be replaced when vibra wrote it, or with --force.
void check_subtitles_file(const fs::path& vtt, bool force) {
  render::resolve_output_file(vtt);
  std::error_code ec;
  if (force || !fs::exists(vtt, ec)) return;
  const std::string head = render::read_text_file(vtt).substr(0, 64);
  if (head.rfind(std::string("WEBVTT\n\n") + render::kWebVttMark, 0) != 0)
    throw render::OutputError("'" + vtt.string() + "' exists and was not written by vibra lecture: move it away, or "
                              "add --force to replace it");
}

long long total_frames(const std::vector<const PlannedShot*>& shots) {
  long long frames = 0;
  for (const PlannedShot* p : shots) frames += p->frames;
  return frames;
}

/// The chapters and cues of the shots in `plan`, one after the other.
void lay_out(const std::vector<const PlannedShot*>& shots, double fps, std::vector<render::VideoChapter>& chapters,
             std::vector<render::SubtitleCue>& cues) {
  long long frame = 0;
  for (const PlannedShot* p : shots) {
    chapters.push_back({p->shot->title, frame, frame + p->frames});
    const double start = double(frame) / fps;
    for (const render::SubtitleCue& c : p->cues)
      if (c.end > c.start) cues.push_back({start + c.start, start + c.end, c.text});
    frame += p->frames;
  }
}
/// What the speaker view shows of a shot: a card's text, a scene's notes.
std::vector<std::string> speaker_notes(const Shot& shot) {
  if (shot.is_card) {  // a card has a text, an equation, or both
    std::vector<std::string> notes;
    if (!shot.card.empty()) notes.push_back(render::rich_text_plain(shot.card));
    if (!shot.equation.empty()) notes.push_back(render::formula_plain_text(shot.equation));
    return notes;
  }
  std::vector<std::string> notes;
  for (const std::string& spec : shot.scene.notes) {
    const Note note = parse_note(spec);
    notes.push_back("t = " + short_number(note.from) + " to " + short_number(note.to) + ": " +
                    render::rich_text_plain(note.text));
  }
  return notes;
}

/// Each shot rendered into its own video (`files`, in the shots' order) and first frame, for slides.
std::vector<PresentedShot> presented_shots(const std::vector<const PlannedShot*>& shots,
                                           const std::vector<render::ClipFile>& files, const fs::path& folder,
                                           double fps) {
  std::vector<PresentedShot> out;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const PlannedShot& p = *shots[i];
    PresentedShot shot;
    shot.number = p.shot->number;
    shot.title = p.shot->title;
    shot.video = files.at(i).path;
    shot.still = folder / ("still-" + std::to_string(shot.number) + ".png");
    shot.frames = p.frames;
    shot.seconds = double(p.frames) / fps;
    shot.ending = p.shot->ending;
    shot.notes = speaker_notes(*p.shot);
    shot.interval = p.interval;
    shot.time_map = p.time_map;
    out.push_back(std::move(shot));
  }
  return out;
}

/// --shots-dir's folder as a path with a name of its own ("shots/" -> "shots").
fs::path shots_folder_path(const std::string& option) {
  if (option.empty()) return {};
  fs::path dir = fs::path(option).lexically_normal();
  if (!dir.has_filename()) dir = dir.parent_path();
  const std::string name = dir.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw UsageError("--shots-dir " + quoted_value(option, 80) + ": name a folder of its own for the shots, e.g. "
                     "--shots-dir shots");
  return dir;
}

/// The shots folder built and sealed beside its final place, or nullptr when none is asked for.
std::unique_ptr<render::TemporaryDirectory> staged_shots_folder(const fs::path& dir, const Storyboard& board,
                                                                const std::vector<PresentedShot>& shots,
                                                                const LectureRequest& r) {
  if (dir.empty()) return nullptr;
  auto staged = std::make_unique<render::TemporaryDirectory>(dir.parent_path(), dir.filename().string());
  stage_shots_folder(render::rich_text_plain(board.title), shown_path(r.storyboard), shots, staged->path());
  staged->seal();
  check_companion_folder(dir, r.force);  // again: the user may have put a file there meanwhile
  return staged;
}
}  // namespace

namespace {
/// Refuses options that do not go together, before anything is read.
void check_lecture_options(const LectureRequest& r, bool page, bool per_shot) {
  const std::string ext = render::lower_extension_of(r.output);
  if (ext != ".mp4" && ext != ".webm" && !page)
    throw UsageError("-o " + quoted_value(r.output, 80) + ": a lecture is written as .mp4, .webm or .html (a page)");
  if (r.present && !page) throw UsageError("--present makes a page of slides: give -o TALK.html");
  if (per_shot && (r.segment || r.shot))
    throw UsageError(std::string(r.present ? "--present" : "--shots-dir") + " takes every shot: drop " +
                     (r.segment ? "--segment" : "--shot"));
  if (r.segment && page)
    throw UsageError("--segment renders shot files to join later: give -o LECTURE.mp4 or .webm, not a page");
  if (r.segment && r.shot) throw UsageError("--shot and --segment both choose shots: give one of them");
  if (r.video.transparent) throw UsageError("a lecture cannot be transparent: drop --transparent");
}

/// The storyboard, at --size if given, with --shot checked against it.
Storyboard load_board(const LectureRequest& r) {
  Storyboard board = load_storyboard(r.storyboard);
  if (!r.size.empty()) {
    parse_size(r.size, board.width, board.height);
    for (Shot& shot : board.shots) shot.scene.width = board.width, shot.scene.height = board.height;
  }
  if (r.shot && (*r.shot < 1 || *r.shot > int(board.shots.size())))
    throw UsageError("--shot " + std::to_string(*r.shot) + ": " + r.storyboard + " has shots 1.." +
                     std::to_string(board.shots.size()));
  return board;
}

/// --segment: the chosen shots as shot files beside the output, for a later run to join.
void write_shot_files(const Storyboard& board, const std::vector<PlannedShot>& plan,
                      const std::vector<const PlannedShot*>& chosen, const LectureRequest& r) {
  if (chosen.empty())
    throw UsageError("--segment " + std::to_string(r.segment->index) + "/" + std::to_string(r.segment->count) +
                     " has no shots: the storyboard has " + std::to_string(plan.size()) + ", so use at most that many");
  for (const PlannedShot* p : chosen) {
    const fs::path file = shot_file(r.output, p->shot->number, plan.size());
    render::resolve_output_file(file);
    std::error_code ec;
    if (!r.force && fs::exists(file, ec) && description_of(file).rfind("vibra lecture shot ", 0) != 0)
      throw render::OutputError("'" + file.string() + "' exists and was not written by vibra lecture: move it "
                                "away, or add --force to overwrite it");
  }
  for (const PlannedShot* p : chosen) {
    const fs::path file = shot_file(r.output, p->shot->number, plan.size());
    if (description_of(file) == p->tag) continue;  // already rendered
    render_shot(board, *p, {file}, r);
  }
  if (!r.quiet)
    std::fprintf(stderr, "vibra: wrote %zu shot file(s) beside %s: join them with vibra lecture %s -o %s\n",
                 chosen.size(), r.output.c_str(), r.storyboard.c_str(), r.output.c_str());
}

/// One lecture's run past its checks: what it renders and where it goes.
struct LectureRun {
  const LectureRequest& r;
  const Storyboard& board;
  const std::vector<PlannedShot>& plan;
  std::vector<const PlannedShot*> chosen;
  bool page = false, per_shot = false;
  render::OutputTarget target;
  fs::path shots_dir, companions, vtt;  ///< vtt: beside a video; companions: a page's folder
  std::string stem;
  std::vector<std::string> kinds;  ///< the joined videos' extensions
  std::vector<render::VideoChapter> chapters;
  std::vector<render::SubtitleCue> cues;
  std::optional<render::AudioClip> sound;
  long long frames = 0;
  std::map<std::string, std::string> metadata;
};

/// Every path the run writes, checked before any work.
void check_lecture_paths(const LectureRun& run) {
  if (run.page) check_companion_folder(run.companions, run.r.force);
  else check_subtitles_file(run.vtt, run.r.force);
  if (run.shots_dir.empty()) return;
  if (run.page && fs::absolute(run.shots_dir) == fs::absolute(run.companions))
    throw UsageError("--shots-dir " + run.shots_dir.string() + " is the page's own folder: choose another");
  check_companion_folder(run.shots_dir, run.r.force);
}

/// The shots' clips, one list per kind: reused from a cluster's shot files
/// where complete, else rendered into `clips`. Shots rendered here in a row
/// share one encoder, which starts and drains once for them and runs on
/// across their starts; a kept shot file ends the row and is joined as it
/// is. With per_shot every shot is a file of its own, which its slide plays.
std::vector<std::vector<render::ClipFile>> render_clips(const LectureRun& run, const fs::path& clips) {
  const LectureRequest& r = run.r;
  const std::vector<const PlannedShot*>& chosen = run.chosen;
  std::vector<std::vector<render::ClipFile>> clip_files(run.kinds.size());
  std::unique_ptr<render::FrameSink> row;
  std::vector<fs::path> row_files;
  long long row_frames = 0;
  auto end_row = [&] {
    if (!row) return;
    row->finish();
    row.reset();
    for (std::size_t i = 0; i < run.kinds.size(); ++i) clip_files[i].push_back({row_files[i], row_frames});
  };
  // Which shots a cluster left complete beside the output (read once: each is a file to open).
  std::vector<bool> kept(chosen.size());
  for (std::size_t i = 0; i < chosen.size(); ++i)
    kept[i] = !run.page && !run.per_shot &&
              description_of(shot_file(r.output, chosen[i]->shot->number, run.plan.size())) == chosen[i]->tag;
  // While a card plays (drawn once, then only encoded), the scene shot after
  // it is solved and laid out on a helper thread, so the encoder does not
  // wait for it at the cut. Each thread draws on canvases of its own, with
  // Pango's font map of its own thread.
  std::future<std::unique_ptr<PreparedRender>> next_scene;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const PlannedShot* p = chosen[i];
    // Waiting for the helper, this thread still looks at the stop flag: only it
    // sees a stop the Python module polls for (render/output/stop_signal.hpp).
    while (next_scene.valid() && next_scene.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready)
      render::throw_if_stop_requested();
    std::unique_ptr<PreparedRender> prepared = next_scene.valid() ? next_scene.get() : nullptr;
    if (kept[i]) {
      end_row();
      clip_files[0].push_back({shot_file(r.output, p->shot->number, run.plan.size()), p->frames});
      continue;
    }
    if (run.per_shot) end_row();
    if (!row) {
      row_files.clear();
      for (const std::string& kind : run.kinds)
        row_files.push_back(clips / ("from-shot-" + std::to_string(p->shot->number) + kind));
      row = sink_for(run.board, row_files, run.per_shot ? p->frames : total_frames(chosen), r, "");
      if (run.per_shot)
        row = std::make_unique<render::FirstFrameSink>(
            std::move(row), clips / ("still-" + std::to_string(p->shot->number) + ".png"), run.board.width,
            run.board.height);
      row_frames = 0;
    }
    if (!run.per_shot && p->shot->is_card && i + 1 < chosen.size() && !chosen[i + 1]->shot->is_card && !kept[i + 1])
      next_scene = std::async(std::launch::async,
                              [request = shot_request(run.board, *chosen[i + 1], *row, row_files.front(), r)] {
                                return std::make_unique<PreparedRender>(request);
                              });
    render_shot_into(run.board, *p, *row, row_files.front(), r, std::move(prepared));
    row_frames += p->frames;
  }
  end_row();
  return clip_files;
}

/// A video output: the joined video and its subtitles (and the shots folder) placed together.
void write_lecture_video(const LectureRun& run, const std::vector<std::vector<render::ClipFile>>& clip_files,
                         const fs::path& clips, const render::TemporaryDirectory* shots_stage, const std::string& shots_said) {
  const LectureRequest& r = run.r;
  // Both finished before either is placed, then placed together or not at all.
  render::TemporaryFile subtitles(run.vtt);
  render::write_text(subtitles, render::web_vtt(run.cues, shown_path(r.storyboard)));
  const fs::path joined = clips / run.target.file.filename();
  render::join_clips(clip_files[0], joined, int(run.board.fps), run.chapters, run.cues, run.metadata,
                     run.sound ? &*run.sound : nullptr);
  std::vector<render::Placement> placements = {{joined, run.target.file}, {subtitles.path(), subtitles.final_path()}};
  if (shots_stage) placements.push_back({shots_stage->path(), run.shots_dir});
  render::place_together(placements);
  if (!r.quiet)
    std::fprintf(stderr, "vibra: wrote %s (%zu shot%s, %lld frames, %.1f s, %zu chapters) and %s%s\n",
                 one_line_message(run.target.shown(), 4096).c_str(), run.chosen.size(),
                 run.chosen.size() == 1 ? "" : "s", run.frames, double(run.frames) / run.board.fps,
                 run.chapters.size(), one_line_message(run.vtt.string(), 4096).c_str(), shots_said.c_str());
}

/// The lecture page's content: its video, chapters, downloads and facts.
render::LecturePage lecture_page_of(const LectureRun& run, const std::string& folder) {
  const Storyboard& board = run.board;
  const std::string base = folder + run.stem;
  render::LecturePage lecture;
  lecture.title = render::rich_text_plain(board.title);
  render::PageMedia& media = lecture.media;
  media.kind = render::PageMedia::Kind::video;
  media.width = board.width + (board.width & 1), media.height = board.height + (board.height & 1);
  media.frames = run.frames;
  media.fps = board.fps;
  media.frame_interval = 1 / board.fps;
  media.videos = {base + ".mp4", base + ".webm"};
  media.subtitles = base + ".vtt";
  media.sound = run.sound.has_value();
  for (const auto& c : run.chapters) lecture.chapters.push_back({c.title, double(c.first_frame) / board.fps});
  lecture.downloads = {{"MP4 video", base + ".mp4"}, {"WebM video", base + ".webm"}, {"Subtitles (WebVTT)", base + ".vtt"}};
  lecture.facts = {{"storyboard", shown_path(run.r.storyboard)},
                   {"shots", std::to_string(run.chosen.size())},
                   {"frames", std::to_string(run.frames) + " at " + std::to_string(int(board.fps)) + " fps (" +
                                  std::to_string(int(std::lround(double(run.frames) / board.fps))) + " s of video)"},
                   {"size", std::to_string(board.width) + "x" + std::to_string(board.height)}};
  lecture.command_line = run.r.command_line;
  return lecture;
}

/// A page output: its videos, subtitles and (--present) slides staged in
/// PAGE_files/, then the folder, the page (and the shots folder) placed together.
void write_lecture_page(const LectureRun& run, const std::vector<std::vector<render::ClipFile>>& clip_files,
                        const std::vector<PresentedShot>& presented, const render::TemporaryDirectory* shots_stage,
                        const std::string& shots_said) {
  const LectureRequest& r = run.r;
  render::TemporaryDirectory staged(run.companions.parent_path(), run.companions.filename().string());
  render::TemporaryFile page_file(run.target.file);
  const std::string folder = run.companions.filename().string() + "/";
  render::write_text_file(staged.path() / (run.stem + ".vtt"), render::web_vtt(run.cues, shown_path(r.storyboard)));
  for (std::size_t i = 0; i < run.kinds.size(); ++i)
    render::join_clips(clip_files[i], staged.path() / (run.stem + run.kinds[i]), int(run.board.fps), run.chapters,
                       run.cues, run.metadata, run.sound ? &*run.sound : nullptr);
  if (r.present) {  // the slides, and the one-file video and subtitles to download
    render::Presentation show = stage_presentation(
        render::rich_text_plain(run.board.title), run.board.width, run.board.height, run.board.fps, presented,
        staged.path(), folder,
        {{"The whole lecture (MP4)", folder + run.stem + ".mp4"}, {"Subtitles (WebVTT)", folder + run.stem + ".vtt"}});
    show.command_line = r.command_line;
    render::write_text(page_file, render::presentation_html(show));
  } else {
    render::write_text(page_file, render::lecture_page_html(lecture_page_of(run, folder)));
  }
  staged.seal();
  check_companion_folder(run.companions, r.force);  // again: the user may have put a file there meanwhile
  std::vector<render::Placement> placements = {{staged.path(), run.companions}, {page_file.path(), page_file.final_path()}};
  if (shots_stage) placements.push_back({shots_stage->path(), run.shots_dir});
  render::place_together(placements);
  if (!r.quiet)
    std::fprintf(stderr, "vibra: wrote %s and %s (%zu %s, %lld frames, %.1f s)%s\n",
                 one_line_message(run.target.shown(), 4096).c_str(),
                 one_line_message(run.companions.string(), 4096).c_str(), run.chapters.size(),
                 r.present ? "slides" : "chapters", run.frames, double(run.frames) / run.board.fps, shots_said.c_str());
}

/// A narrated lecture's presented shots each get their own part of the
/// speech: a shot that speaks is joined again with its sound (packets
/// copied, the audio encoded), so its slide and its file in the shots
/// folder speak as the one-file video does.
void voice_presented_shots(const LectureRun& run, std::vector<PresentedShot>& presented, const fs::path& clips) {
  for (std::size_t i = 0; i < presented.size(); ++i) {
    const std::optional<render::AudioClip> sound = sound_of({run.chosen[i]}, run.board.fps);
    if (!sound) continue;  // a silent shot stays as it is
    PresentedShot& shot = presented[i];
    const fs::path voiced = clips / ("voiced-" + std::to_string(shot.number) + shot.video.extension().string());
    render::join_clips({{shot.video, shot.frames}}, voiced, int(run.board.fps), {}, {}, run.metadata, &*sound);
    shot.video = voiced;
    shot.sound = true;
  }
}

void make_lecture(const LectureRequest& r) {
  const bool page = render::classify_output(r.output) == render::OutputKind::page;
  const bool per_shot = r.present || !r.shots_dir.empty();  // each shot a video of its own, and its first frame
  check_lecture_options(r, page, per_shot);
  const fs::path shots_dir = shots_folder_path(r.shots_dir);
  note_input_file(r.storyboard, "the storyboard");  // before the outputs are checked: never written over
  const render::OutputTarget target = render::resolve_output(r.output, render::kNeedsAFile);
  render::refuse_input_as_output(target.file);
  render::check_output_settings(page ? "x.mp4" : r.output, false, r.video);

  Storyboard board = load_board(r);
  render::start_loading_fonts();
  const std::vector<ShotNarration> narration = narrate_lecture(board);  // speech made before any frame
  fit_shots_to_speech(board, narration);
  const std::vector<PlannedShot> plan = plan_lecture(board, r.video, narration);  // every shot checked before any work
  if (r.script) return write_script(board, plan);
  LectureRun run{r, board, plan};
  for (const PlannedShot& p : plan)
    if (r.shot ? p.shot->number == *r.shot : !r.segment || (p.shot->number - 1) % r.segment->count == r.segment->index)
      run.chosen.push_back(&p);
  if (r.segment) return write_shot_files(board, plan, run.chosen, r);  // shot files for a cluster, beside the output

  run.page = page, run.per_shot = per_shot, run.target = target, run.shots_dir = shots_dir;
  run.stem = fs::path(r.output).stem().string();
  run.companions = page ? companion_folder(r.output) : fs::path();
  run.vtt = page ? fs::path() : target.file.parent_path() / (run.stem + ".vtt");
  check_lecture_paths(run);
  lay_out(run.chosen, board.fps, run.chapters, run.cues);
  for (const auto& c : run.chapters) run.frames = c.end_frame;
  run.sound = r.mute ? std::nullopt : sound_of(run.chosen, board.fps);
  run.kinds = page && !r.present ? std::vector<std::string>{".mp4", ".webm"}
                                 : std::vector<std::string>{page ? ".mp4" : render::lower_extension_of(r.output)};
  run.metadata = {{"title", render::rich_text_plain(board.title)}, {"comment", "vibra lecture " + shown_path(r.storyboard)}};

  render::TemporaryDirectory clips(target.file.parent_path(), run.stem + "_shots");
  const std::vector<std::vector<render::ClipFile>> clip_files = render_clips(run, clips.path());
  std::vector<PresentedShot> presented =
      per_shot ? presented_shots(run.chosen, clip_files[0], clips.path(), board.fps) : std::vector<PresentedShot>{};
  if (run.sound) voice_presented_shots(run, presented, clips.path());
  // Copied before the page's folder takes the shots' files: rendered once, for both.
  const std::unique_ptr<render::TemporaryDirectory> shots_stage = staged_shots_folder(shots_dir, board, presented, r);
  const std::string shots_said =
      shots_stage ? ", and " + std::to_string(presented.size()) + " shots in " + one_line_message(shots_dir.string(), 4096) : "";
  if (page) write_lecture_page(run, clip_files, presented, shots_stage.get(), shots_said);
  else write_lecture_video(run, clip_files, clips.path(), shots_stage.get(), shots_said);
}

}  // namespace

void run_lecture(const LectureRequest& r) {
  try {
    make_lecture(r);
  } catch (const render::OutputError& e) {
    throw render::OutputError(render::said_of_output(e.what(), r.output));  // a full disk names OUT, not a temporary
  }
}

}  // namespace vibra::scenes
