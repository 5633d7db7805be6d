// Writes the chapter site's index.html: one section per figure or exercise, in the chapter's order.
#include "cli/chapter/chapter_index.hpp"

#include <algorithm>
#include <filesystem>

#include "cli/chapter/chapter_jobs.hpp"
#include "render/page/web_text.hpp"

namespace vibra::cli {

namespace {
using render::html_escape;

constexpr size_t kShownLines = 24;  // standard output shown on the page; the rest is a link away

const char* const kStyle =
    "body{font:16px/1.45 system-ui,sans-serif;max-width:60rem;margin:2rem auto;padding:0 1rem;color:#222}"
    "section{border-top:1px solid #ccc;padding-top:.5rem;margin-top:2rem}"
    "pre{background:#f4f4f4;padding:.5rem;overflow-x:auto;font-size:13px}pre.cmd{background:#e8eef8}"
    "img,video{max-width:100%;height:auto;display:block;margin:.5rem 0}"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.2rem .5rem;text-align:left}"
    ".differs{background:#fdd}.note{background:#fff6d8;padding:.5rem}nav{display:flex;flex-wrap:wrap;gap:.2rem .5rem}";

/// Where a file links: relative, so the site works from file:// and anywhere it is copied.
std::string link(const std::string& file) { return html_escape(render::url_path_escape(file)); }

std::string output_html(const std::string& file, const std::string& alt) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".png" || ext == ".svg")
    return "<img src=\"" + link(file) + "\" alt=\"" + html_escape(alt) + "\" loading=\"lazy\">\n";
  if (ext == ".mp4" || ext == ".webm")
    return "<video src=\"" + link(file) + "\" controls loop muted preload=\"metadata\"></video>\n";
  return "<p>Wrote <a href=\"" + link(file) + "\">" + html_escape(file) + "</a>.</p>\n";
}

/// The first lines of a command's standard output, and a link to all of it.
std::string text_html(const CommandResult& command) {
  if (command.text_file.empty()) return "";
  const size_t lines = static_cast<size_t>(std::count(command.text.begin(), command.text.end(), '\n'));
  size_t cut = 0;
  for (size_t shown = 0; shown < kShownLines && cut < command.text.size(); ++shown)
    cut = std::min(command.text.find('\n', cut), command.text.size()) + 1;
  std::string html = "<pre class=\"out\">" + html_escape(command.text.substr(0, cut)) + "</pre>\n";
  if (lines > kShownLines)
    html += "<p>First " + std::to_string(kShownLines) + " of " + std::to_string(lines) + " lines: ";
  else
    html += "<p>";
  return html + "<a href=\"" + link(command.text_file) + "\">" + html_escape(command.text_file) + "</a></p>\n";
}

std::string numbers_html(const std::vector<NumberResult>& numbers) {
  if (numbers.empty()) return "";
  std::string html = "<table class=\"numbers\"><tr><th>quantity</th><th>the book</th><th>vibra</th><th></th></tr>\n";
  for (const NumberResult& n : numbers) {
    const std::string verdict = n.agrees ? "agrees" : n.vibra.empty() ? "not in the output" : "differs";
    html += std::string("<tr") + (n.agrees ? "" : " class=\"differs\"") + "><td>" +
            html_escape(quantity_name(*n.number)) + "</td><td>" + html_escape(n.number->book) + "</td><td>" +
            html_escape(n.vibra) + "</td><td>" + verdict +
            (n.number->note.empty() ? "" : ": " + html_escape(n.number->note)) + "</td></tr>\n";
  }
  return html + "</table>\n";
}

std::string item_html(const ItemResult& result) {
  const ChapterItem& item = *result.item;
  std::string html =
      "<section id=\"" + item_key(item) + "\">\n<h2>" + item_name(item) + ": " + html_escape(item.title) + "</h2>\n";
  for (const CommandResult& command : result.commands) {
    html += "<pre class=\"cmd\">" + html_escape(shown_command(command.args)) + "</pre>\n";
    if (!command.output.empty()) html += output_html(command.output, item_name(item) + ": " + item.title);
    html += text_html(command);
  }
  html += numbers_html(result.numbers);
  if (!item.note.empty()) html += "<p class=\"note\">Where the book differs: " + html_escape(item.note) + "</p>\n";
  return html + "</section>\n";
}
}  // namespace

std::string chapter_index_html(const std::vector<ItemResult>& items, const std::string& only) {
  size_t numbers = 0, agree = 0;
  for (const ItemResult& item : items)
    for (const NumberResult& n : item.numbers) numbers += 1, agree += n.agrees ? 1 : 0;
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"generator\" content=\"vibra chapter\">\n<title>Chapter 1: vibration ODEs, by vibra</title>\n"
      "<style>" +
      std::string(kStyle) +
      "</style>\n</head>\n<body>\n<h1>Chapter 1: vibration ODEs, by vibra</h1>\n"
      "<p>Every figure (1.1-1.22) and exercise (1.1-1.28) of chapter 1 of Linge &amp; Langtangen, <i>Finite "
      "Difference Computing with PDEs</i> (2017), made again by the vibra command shown with it. Where the book "
      "prints a number, vibra's is beside it: " +
      std::to_string(agree) + " of " + std::to_string(numbers) + " agree.</p>\n";
  if (!only.empty()) html += "<p>Only the items of <code>--only " + html_escape(only) + "</code>.</p>\n";
  html += "<nav>";
  for (const ItemResult& item : items)
    html += "<a href=\"#" + item_key(*item.item) + "\">" + item_key(*item.item) + "</a>";
  html += "</nav>\n";
  for (const ItemResult& item : items) html += item_html(item);
  return html + "<p>Made by <code>vibra chapter</code>.</p>\n</body>\n</html>\n";
}

}  // namespace vibra::cli
