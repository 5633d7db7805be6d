// The lecture page: one HTML file with the run's video or frames, its plots, facts and player.
#include "render/page/html_page.hpp"

#include <fstream>
#include <iterator>

#include <cstdio>
#include <map>

#include "render/output/output_error.hpp"
#include "render/output/temporary_file.hpp"
#include "render/page/page_assets.hpp"
#include "render/page/page_parts.hpp"
#include "render/page/web_text.hpp"

namespace vibra::render {

namespace {
std::string mime_type(const std::string& source) {
  const std::string ext = std::filesystem::path(source).extension().string();
  if (ext == ".mp4") return "video/mp4";
  if (ext == ".webm") return "video/webm";
  if (ext == ".ogv") return "video/ogg";
  return "video/x-matroska";
}

std::string media_html(const PageMedia& m) {
  const std::string size = " width=\"" + std::to_string(m.width) + "\" height=\"" + std::to_string(m.height) + "\"";
  switch (m.kind) {
    case PageMedia::Kind::none: return "";
    case PageMedia::Kind::frames:
      return "<div id=\"media\"><img id=\"frames\"" + size + " alt=\"a frame of the animation\"></div>";
    case PageMedia::Kind::video: break;
  }
  const std::string playing = m.sound ? "" : " muted loop";  // a silent animation loops; a lecture speaks, once
  std::string out = "<div id=\"media\"><video id=\"video\" preload=\"auto\" playsinline" + playing + size + ">\n";
  for (const auto& s : m.videos) out += "  <source src=\"" + page_href(s) + "\" type=\"" + mime_type(s) + "\">\n";
  if (!m.subtitles.empty())
    out += "  <track kind=\"subtitles\" label=\"Notes\" srclang=\"en\" src=\"" + page_href(m.subtitles) + "\" default>\n";
  if (!m.videos.empty())
    out += "  Your browser plays none of these videos: download <a href=\"" + page_href(m.videos.front()) + "\">" +
           html_escape(m.videos.front()) + "</a>.\n";
  return out + "</video></div>";
}

/// The lecture's chapters: links that seek the video to each shot.
std::string chapters_html(const std::vector<PageChapter>& chapters) {
  if (chapters.empty()) return "";
  std::string out = "<ol id=\"chapters\">\n";
  for (const PageChapter& c : chapters) {
    char start[32];
    std::snprintf(start, sizeof start, "%d:%04.1f", int(c.start) / 60, c.start - 60 * (int(c.start) / 60));
    out += "<li><a href=\"#\" data-start=\"" + json_number(c.start) + "\">" + html_escape(c.title) + "</a> <span>" + start +
           "</span></li>\n";
  }
  return out + "</ol>";
}

std::string data_json(const LecturePage& page) {
  const PageMedia& m = page.media;
  std::string out = "{\"media\":";
  switch (m.kind) {
    case PageMedia::Kind::none: out += "{\"kind\":\"none\"},\"clock\":null"; break;
    case PageMedia::Kind::video: out += "{\"kind\":\"video\"}"; break;
    case PageMedia::Kind::frames:
      out += "{\"kind\":\"frames\",\"prefix\":" + json_string(url_path_escape(m.frames_prefix)) +
             ",\"digits\":" + std::to_string(m.digits) + "}";
      break;
  }
  if (m.kind != PageMedia::Kind::none)
    out += ",\"clock\":{\"fps\":" + json_number(m.fps) + ",\"frames\":" + std::to_string(m.frames) +
           ",\"interval\":" + json_number(m.frame_interval) + page_time_map_json(m.time_map) + "}";
  return out + ",\"plots\":" + page_plots_json(page.panels, kPagePlotBudgetBytes) + "}";
}

std::string facts_rows(const PageFacts& facts) {
  std::string out;
  for (const auto& [name, value] : facts)
    out += "<tr><td>" + html_escape(name) + "</td><td>" + html_escape(value) + "</td></tr>\n";
  return out;
}

}  // namespace

std::string lecture_page_html(const LecturePage& page) {
  const bool has_media = page.media.kind != PageMedia::Kind::none;
  const std::string hint =
      has_media ? "Space plays or pauses; &#8592; and &#8594; step one frame; Home and End go to the ends. Click or drag "
                  "in a plot to seek. The wheel zooms the time axis; Shift+drag, or a drag on the time axis, pans; "
                  "a double-click shows the whole run."
                : "Click in a plot to mark a time. The wheel zooms the time axis; Shift+drag, or a drag on the time "
                  "axis, pans; a double-click shows the whole run.";
  return fill_page_template(page_asset("lecture.html.in"),
              {{"TITLE", html_escape(page.title)},
               {"UPLOT_CSS", std::string(page_asset("uPlot.min.css"))},
               {"PAGE_CSS", std::string(page_asset("page.css"))},
               {"MEDIA", media_html(page.media) + chapters_html(page.chapters)},
               {"CONTROLS_CLASS", has_media ? "" : "hidden"},
               {"HINT", hint},
               {"FACTS", facts_rows(page.facts)},
               {"COMMAND", html_escape(page.command_line)},
               {"DOWNLOADS", page_downloads_html(page.downloads)},
               {"DATA", data_json(page)},
               {"UPLOT_JS", std::string(page_asset("uPlot.iife.min.js"))},
               {"PAGE_JS", std::string(page_asset("page.js"))}});
}

void write_text(const TemporaryFile& file, const std::string& text) {
  const std::string path = file.final_path().string();
  std::FILE* f = std::fopen(file.path().c_str(), "wb");
  if (!f) throw OutputError("cannot write '" + path + "': choose a writable path");
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) throw OutputError("writing '" + path + "' failed (disk full?)");
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  TemporaryFile file(path);
  write_text(file, text);
  file.commit();
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.is_open() || in.bad()) throw OutputError("cannot read '" + path.string() + "': check the disk and its permissions");
  return text;
}

}  // namespace vibra::render
