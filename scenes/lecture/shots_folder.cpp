// vibra lecture --shots-dir: every shot as its own video and first-frame PNG, with index.md and a Beamer snippet.
#include "scenes/lecture/shots_folder.hpp"

#include <algorithm>
#include <cstdio>

#include "render/output/output_error.hpp"
#include "render/output/stop_signal.hpp"
#include "render/page/html_page.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {
void copy_shot_file(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw render::OutputError("cannot copy a shot to '" + to.string() + "': " + ec.message() + " (disk full?)");
}

/// Characters a table cell or LaTeX text would read as markup, and what stands for each.
std::string escaped(const std::string& text, const std::vector<std::pair<char, const char*>>& table) {
  std::string out;
  for (char c : text) {
    auto it = std::find_if(table.begin(), table.end(), [c](const auto& row) { return row.first == c; });
    if (it == table.end()) out += c;
    else out += it->second;
  }
  return out;
}

const std::vector<std::pair<char, const char*>> kMarkdownCell = {{'|', "\\|"}, {'\\', "\\\\"}, {'*', "\\*"},
                                                                 {'_', "\\_"}, {'<', "&lt;"}, {'`', "\\`"}};
const std::vector<std::pair<char, const char*>> kLatexText = {
    {'\\', "\\textbackslash{}"}, {'{', "\\{"}, {'}', "\\}"}, {'$', "\\$"}, {'&', "\\&"}, {'#', "\\#"},
    {'^', "\\^{}"}, {'_', "\\_"}, {'%', "\\%"}, {'~', "\\~{}"}};

std::string seconds_cell(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

std::string index_md(const std::string& title, const std::string& storyboard, const std::vector<PresentedShot>& shots) {
  std::string out = "# " + escaped(title, kMarkdownCell) + ": the shots\n\nWritten by vibra lecture from `" +
                    storyboard + "`: every shot as its own video, starting on a keyframe, and its first frame as "
                    "a PNG, for slides in PowerPoint, Keynote or Impress (insert the video; the PNG is its poster) "
                    "and in Beamer (`beamer.tex`).\n\n"
                    "| shot | title | video | first frame | seconds | at its end |\n|---:|---|---|---|---:|---|\n";
  for (const PresentedShot& shot : shots) {
    const std::string stem = shot_file_stem(shot, shots.size()), video = stem + shot.video.extension().string();
    out += "| " + std::to_string(shot.number) + " | " + escaped(shot.title, kMarkdownCell) + " | [" + video + "](" +
           video + ") | ![shot " + std::to_string(shot.number) + "](" + stem + ".png) | " +
           seconds_cell(shot.seconds) + " | " + shot_end_word(shot.ending.then) + " |\n";
  }
  return out;
}

std::string beamer_tex(const std::string& title, const std::vector<PresentedShot>& shots) {
  std::string out = "% Beamer frames for the shots of \"" + title + "\", written by vibra lecture.\n"
                    "% \\input{beamer.tex} in a document with \\usepackage{multimedia}, beside these files:\n"
                    "% each frame shows the shot's first frame, and a click on it plays the video in PDF\n"
                    "% viewers that can (\\movie); the video's path is relative to the PDF.\n";
  for (const PresentedShot& shot : shots) {
    const std::string stem = shot_file_stem(shot, shots.size());
    out += "\n\\begin{frame}{" + escaped(shot.title, kLatexText) + "}\n  \\centering\n  \\movie{\\includegraphics"
           "[width=0.9\\textwidth]{" + stem + ".png}}{" + stem + shot.video.extension().string() + "}\n\\end{frame}\n";
  }
  return out;
}
}  // namespace

void stage_shots_folder(const std::string& title, const std::string& storyboard,
                        const std::vector<PresentedShot>& shots, const fs::path& staged) {
  for (const PresentedShot& shot : shots) {
    render::throw_if_stop_requested();
    const std::string stem = shot_file_stem(shot, shots.size());
    copy_shot_file(shot.video, staged / (stem + shot.video.extension().string()));
    copy_shot_file(shot.still, staged / (stem + ".png"));
  }
  render::write_text_file(staged / "index.md", index_md(title, storyboard, shots));
  render::write_text_file(staged / "beamer.tex", beamer_tex(title, shots));
}

}  // namespace vibra::scenes
