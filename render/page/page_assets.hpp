// The lecture page's template, script, style and uPlot, compiled into the program at build time.
#pragma once
#include <string>
#include <string_view>

namespace vibra::render {

/// A file the lecture page is made of, compiled in at build time by name:
/// lecture.html.in (the template), page.js, page.css (render/page/);
/// present.html.in, present.js, present.css (the presentation page); and
/// uPlot.iife.min.js, uPlot.min.css (third_party/uplot/). Throws
/// std::logic_error for any other name.
std::string_view page_asset(std::string_view name);

}  // namespace vibra::render
