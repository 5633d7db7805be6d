// Pieces the lecture and presentation pages share: the template filler, numbers and clocks in JSON, download links.
#include "render/page/page_parts.hpp"

#include <cstdio>

#include "render/page/web_text.hpp"

namespace vibra::render {

std::string page_href(const std::string& file) { return html_escape(url_path_escape(file)); }

std::string json_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

/// ,"map":[[video, simulated, rate], ...] for a paced clock; nothing for a steady one.
std::string page_time_map_json(const std::vector<PageMedia::TimePiece>& pieces) {
  if (pieces.empty()) return "";
  std::string out = ",\"map\":[";
  for (std::size_t i = 0; i < pieces.size(); ++i)
    out += (i ? ",[" : "[") + json_number(pieces[i].video) + "," + json_number(pieces[i].simulated) + "," +
           json_number(pieces[i].rate) + "]";
  return out + "]";
}

std::string page_downloads_html(const std::vector<PageDownload>& downloads) {
  if (downloads.empty()) return "";
  std::string out = "<p class=\"downloads\">Download:";
  for (size_t i = 0; i < downloads.size(); ++i)
    out += std::string(i ? " &middot;" : "") + " <a href=\"" + page_href(downloads[i].file) + "\" download>" +
           html_escape(downloads[i].label) + "</a>";
  return out + "</p>";
}

/// Replaces each @NAME@ of the template by its value, in one pass: values
/// (scripts, data) are never searched for names themselves.
std::string fill_page_template(std::string_view text, const std::map<std::string, std::string>& values) {
  std::string out;
  size_t at = 0;
  while (true) {
    const size_t open = text.find('@', at);
    const size_t close = open == std::string_view::npos ? open : text.find('@', open + 1);
    if (close == std::string_view::npos) break;
    const auto value = values.find(std::string(text.substr(open + 1, close - open - 1)));
    if (value == values.end()) {
      out += text.substr(at, close - at);
      at = close;
      continue;
    }
    out += text.substr(at, open - at);
    out += value->second;
    at = close + 1;
  }
  return out += text.substr(at);
}

}  // namespace vibra::render
