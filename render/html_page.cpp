#include "render/html_page.hpp"

#include <cstdio>

#include "render/output_error.hpp"
#include "render/temporary_file.hpp"

namespace vibra::render {

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {
std::string mime_type(const std::string& source) {
  auto ends = [&](const char* ext) {
    const std::string e(ext);
    return source.size() >= e.size() && source.compare(source.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".mp4")) return "video/mp4";
  if (ends(".webm")) return "video/webm";
  if (ends(".ogv")) return "video/ogg";
  return "video/x-matroska";
}

std::string head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escape(title) +
         "</title>\n<style>\n"
         "body { font-family: 'DejaVu Sans', sans-serif; margin: 2em auto; max-width: 1320px; color: #1a1a1f; }\n"
         "video, img { max-width: 100%; height: auto; border: 1px solid #ddd; }\n"
         "table { border-collapse: collapse; margin-top: 1em; }\n"
         "td { padding: 0.15em 1em 0.15em 0; } td:first-child { color: #666; }\n"
         "button, input { font-size: 1em; margin-right: 0.5em; }\n"
         "</style>\n</head>\n<body>\n<h1>" +
         html_escape(title) + "</h1>\n";
}

std::string facts_table(const PageFacts& facts) {
  std::string out = "<table>\n";
  for (const auto& [name, value] : facts)
    out += "<tr><td>" + html_escape(name) + "</td><td>" + html_escape(value) + "</td></tr>\n";
  return out + "</table>\n";
}
}  // namespace

std::string video_page_html(const std::string& title, const std::vector<std::string>& sources, int width, int height,
                            const PageFacts& facts) {
  std::string out = head(title);
  out += "<video controls loop preload=\"auto\" width=\"" + std::to_string(width) + "\" height=\"" +
         std::to_string(height) + "\">\n";
  for (const auto& s : sources)
    out += "  <source src=\"" + html_escape(s) + "\" type=\"" + mime_type(s) + "\">\n";
  out += "  Your browser plays none of these formats: download <a href=\"" + html_escape(sources.front()) + "\">" +
         html_escape(sources.front()) + "</a>.\n</video>\n";
  return out + facts_table(facts) + "</body>\n</html>\n";
}

std::string frames_player_html(const std::string& title, const std::string& prefix, int digits, long long frames,
                               double fps, int width, int height, const PageFacts& facts) {
  char settings[256];
  std::snprintf(settings, sizeof settings, "const frames = %lld, digits = %d; let fps = %g;\n", frames, digits, fps);
  std::string out = head(title);
  out += "<img id=\"frame\" width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" alt=\"frame\">\n";
  out += "<p><button id=\"play\">Pause</button><button id=\"back\">&#9664; step</button>"
         "<button id=\"next\">step &#9654;</button>\n"
         "speed <input id=\"speed\" type=\"range\" min=\"1\" max=\"120\" value=\"" +
         std::to_string(static_cast<int>(fps)) +
         "\"> <span id=\"fps\"></span> frames/s &nbsp; frame <span id=\"index\"></span> of " + std::to_string(frames) +
         "</p>\n";
  out += facts_table(facts);
  out += "<script>\n" + std::string(settings) + "const prefix = \"" + html_escape(prefix) + "\";\n" + R"(let k = 0, playing = true, timer = null;
const img = document.getElementById('frame');
const name = i => prefix + String(i).padStart(digits, '0') + '.png';
function show(i) {
  k = (i + frames) % frames;
  img.src = name(k);
  document.getElementById('index').textContent = k;
  new Image().src = name((k + 1) % frames);  // preload the next frame
}
function schedule() {
  clearInterval(timer);
  document.getElementById('fps').textContent = fps;
  if (playing) timer = setInterval(() => show(k + 1), 1000 / fps);
}
document.getElementById('play').onclick = e => { playing = !playing; e.target.textContent = playing ? 'Pause' : 'Play'; schedule(); };
document.getElementById('next').onclick = () => show(k + 1);
document.getElementById('back').onclick = () => show(k - 1);
document.getElementById('speed').oninput = e => { fps = Number(e.target.value); schedule(); };
show(0);
schedule();
</script>
</body>
</html>
)";
  return out;
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  TemporaryFile file(path);
  std::FILE* f = std::fopen(file.path().c_str(), "wb");
  if (!f) throw OutputError("cannot write '" + path.string() + "': choose a writable path");
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) throw OutputError("writing '" + path.string() + "' failed (disk full?)");
  file.commit();
}

}  // namespace vibra::render
