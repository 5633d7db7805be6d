#include "scenes/run_caption.hpp"

#include <cstdio>

namespace vibra::scenes {

std::string markup_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

std::string run_caption(const std::string& model, const Parameters& p, const TimeMesh& mesh) {
  std::string caption = model + " · " + std::string(scheme_info(mesh.scheme).name);
  char dt[64];
  std::snprintf(dt, sizeof dt, " · Δ<i>t</i> = %.4g", mesh.dt);
  caption += dt;
  for (const auto& a : p.given_assignments()) {
    const std::string key = a.substr(0, a.find('='));
    if (key != "scheme" && key != "dt" && key != "steps_per_period" && key != "T" && key != "periods")
      caption += " · " + markup_escaped(a);
  }
  return caption;
}

}  // namespace vibra::scenes
