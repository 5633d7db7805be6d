// Pieces the lecture and presentation pages share: the template filler, numbers and clocks in JSON, download links.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "render/page/html_page.hpp"

namespace vibra::render {

/// A file relative to the page as an attribute value (percent-encoded, then HTML-escaped).
std::string page_href(const std::string& file);

/// A double as JSON, to the last bit (%.17g).
std::string json_number(double x);

/// ,"map":[[video, simulated, rate], ...] for a paced clock; nothing for a steady one.
std::string page_time_map_json(const std::vector<PageMedia::TimePiece>& pieces);

/// "Download: MP4 video · ..." as a paragraph of links ("" for none).
std::string page_downloads_html(const std::vector<PageDownload>& downloads);

/// Replaces each @NAME@ of a page template by its value, in one pass:
/// values (scripts, data) are never searched for names themselves.
std::string fill_page_template(std::string_view text, const std::map<std::string, std::string>& values);

}  // namespace vibra::render
