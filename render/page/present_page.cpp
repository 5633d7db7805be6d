// The presentation page: a lecture's shots as slides that wait for the presenter, with keys, loops and a speaker view.
#include "render/page/present_page.hpp"

#include "render/page/page_assets.hpp"
#include "render/page/page_parts.hpp"
#include "render/page/web_text.hpp"

namespace vibra::render {

namespace {
/// One <section> a slide: its video, loaded by the script only near the
/// current slide, and its first frame as the poster, shown at once.
std::string slides_html(const Presentation& p) {
  std::string out;
  const std::string size = " width=\"" + std::to_string(p.width) + "\" height=\"" + std::to_string(p.height) + "\"";
  for (std::size_t i = 0; i < p.slides.size(); ++i) {
    const PresentSlide& s = p.slides[i];
    out += "<section class=\"slide\" id=\"slide-" + std::to_string(i + 1) + "\" aria-label=\"" + html_escape(s.title) +
           "\" hidden><video" + (s.sound ? "" : " muted") + " playsinline preload=\"none\"" + size + " poster=\"" + page_href(s.still) +
           "\" data-src=\"" + page_href(s.video) + "\"></video></section>\n";
  }
  return out;
}

std::string notes_json(const std::vector<std::string>& notes) {
  std::string out = "[";
  for (std::size_t i = 0; i < notes.size(); ++i) out += (i ? "," : "") + json_string(notes[i]);
  return out + "]";
}

/// What the script needs of a slide: how it ends, its notes, its clock.
std::string slide_json(const PresentSlide& s) {
  std::string out = "{\"title\":" + json_string(s.title) + ",\"still\":" + json_string(url_path_escape(s.still)) +
                    ",\"frames\":" + std::to_string(s.frames) + ",\"then\":" + json_string(s.then) +
                    ",\"intro\":" + json_number(s.intro) + ",\"sound\":" + (s.sound ? "true" : "false") +
                    ",\"notes\":" + notes_json(s.notes);
  if (s.interval > 0) out += ",\"clock\":{\"interval\":" + json_number(s.interval) + page_time_map_json(s.time_map) + "}";
  return out + "}";
}

std::string data_json(const Presentation& p) {
  std::string out = "{\"title\":" + json_string(p.title) + ",\"fps\":" + json_number(p.fps) + ",\"slides\":[";
  for (std::size_t i = 0; i < p.slides.size(); ++i) out += (i ? ",\n" : "\n") + slide_json(p.slides[i]);
  return out + "]}";
}
}  // namespace

std::string presentation_html(const Presentation& p) {
  return fill_page_template(page_asset("present.html.in"),
                            {{"TITLE", html_escape(p.title)},
                             {"PRESENT_CSS", std::string(page_asset("present.css"))},
                             {"SLIDES", slides_html(p)},
                             {"DOWNLOADS", page_downloads_html(p.downloads)},
                             {"COMMAND", html_escape(p.command_line)},
                             {"DATA", data_json(p)},
                             {"PRESENT_JS", std::string(page_asset("present.js"))}});
}

}  // namespace vibra::render
