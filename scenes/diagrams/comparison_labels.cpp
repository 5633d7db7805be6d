// What the pictures of a comparison (`plot --compare`, `render --compare`) call its members, as Pango markup.
#include "scenes/diagrams/comparison_labels.hpp"

#include <cstdio>

#include "scenes/overlays/run_caption.hpp"

namespace vibra::scenes {

std::string key_markup(const std::string& key) { return key == "dt" ? "Δ<i>t</i>" : markup_escaped(key); }

std::string member_markup(const Comparison& c, size_t m) {
  const std::string& key = c.request().key;
  if (key == "scheme") return c.value(m);
  std::string value = markup_escaped(c.value(m));
  // An angle in degrees says so: "Theta = 120°" (one in radians ends in rad).
  for (const KeySpec& spec : c.parameters(m).specs())
    if (spec.name == key && spec.kind == ValueKind::angle && value.find("rad") == std::string::npos) value += "°";
  return key_markup(key) + " = " + value;
}

render::Color member_color(const render::Color& first, size_t i) {
  // The figures' order (palette::series), whose hues are far apart first:
  // no member's faded future looks like another's curve.
  return i == 0 ? first : render::palette::series(i);
}

std::string early_end_note(EarlyEnd end, double t) {
  char text[64];
  std::snprintf(text, sizeof text, "%s at <i>t</i> = %.3g", end == EarlyEnd::blew_up ? "blew up" : "left the view", t);
  return text;
}

std::string comparison_caption(const std::string& model, const Comparison& comparison) {
  const std::string& key = comparison.request().key;
  const TimeMesh& mesh = comparison.trajectory(0).info().mesh;
  bool same_scheme = true, same_dt = true;
  for (size_t m = 1; m < comparison.size(); ++m) {
    same_scheme &= comparison.trajectory(m).info().mesh.scheme == mesh.scheme;
    same_dt &= comparison.trajectory(m).info().mesh.dt == mesh.dt;
  }
  std::string caption = setting_facts(comparison.parameters(0), key);
  auto add = [&](const std::string& fact) { caption += (caption.empty() ? "" : " · ") + fact; };
  if (same_dt) add(dt_fact(model, mesh.dt));
  if (same_scheme) add(std::string(scheme_info(mesh.scheme).name));
  add("comparing " + key_markup(key));
  return caption;
}

}  // namespace vibra::scenes
