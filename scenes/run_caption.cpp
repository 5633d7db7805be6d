#include "scenes/run_caption.hpp"

#include <algorithm>
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

std::vector<std::pair<std::string, std::string>> run_facts(const std::string& model, const Parameters& p,
                                                          const TimeMesh& mesh) {
  char dt[32], T[32];
  std::snprintf(dt, sizeof dt, "%.6g", mesh.dt);
  std::snprintf(T, sizeof T, "%.6g", mesh.T);
  std::vector<std::pair<std::string, std::string>> facts = {
      {"model", model}, {"scheme", std::string(scheme_info(mesh.scheme).name)}, {"dt", dt}, {"T", T}};
  for (const auto& a : p.given_assignments()) {
    const std::string key = a.substr(0, a.find('='));
    if (std::none_of(facts.begin(), facts.end(), [&](const auto& f) { return f.first == key; }))
      facts.emplace_back(key, a.substr(a.find('=') + 1));
  }
  return facts;
}

}  // namespace vibra::scenes
