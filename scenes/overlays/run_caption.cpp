// The caption of a run: its model, scheme and settings as facts, made safe for Pango markup.
#include "scenes/overlays/run_caption.hpp"

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "core/input/expression.hpp"
#include "core/comparison.hpp"
#include "core/models/model.hpp"
#include "core/input/name_spelling.hpp"
#include "render/draw/caption.hpp"

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

namespace {
/// A key as the book writes it, in Pango markup: Greek names as letters,
/// one-letter names italic, C_D as C with subscript D.
std::string key_markup(const std::string& key) {
  static const std::pair<const char*, const char*> kGreek[] = {
      {"alpha", "<i>α</i>"}, {"beta", "<i>β</i>"},  {"gamma", "<i>γ</i>"}, {"mu", "<i>μ</i>"},
      {"rho", "<i>ρ</i>"},   {"Theta", "<i>Θ</i>"}, {"Omega", "<i>Ω</i>"}, {"w", "<i>ω</i>"},
      {"eps", "<i>ε</i>"},   {"eps_v", "<i>ε</i><sub>v</sub>"}};
  for (const auto& [name, markup] : kGreek)
    if (key == name) return markup;
  const size_t under = key.find('_');
  const std::string stem = key.substr(0, under);
  std::string out = stem.size() == 1 ? "<i>" + markup_escaped(stem) + "</i>" : markup_escaped(stem);
  if (under != std::string::npos) out += "<sub>" + markup_escaped(key.substr(under + 1)) + "</sub>";
  return out;
}

/// A key's unit as a symbol after its value ("kg", "N/m", "°"); "" for the
/// dimension words of a scaled model ("length", "time", "mass").
std::string unit_symbol(const std::string& unit) {
  static const std::pair<const char*, const char*> kSymbols[] = {
      {"deg", "°"},         {"deg/time", ""},   {"m/s^2", "m/s²"}, {"kg/m^3", "kg/m³"}, {"ohm", "Ω"},
      {"N s/m", "N·s/m"},   {"kg", "kg"},       {"m", "m"},        {"m/s", "m/s"},       {"N/m", "N/m"},
      {"H", "H"},           {"F", "F"},         {"V", "V"},        {"A", "A"},           {"C", "C"},
      {"s", "s"},           {"N", "N"}};
  for (const auto& [name, symbol] : kSymbols)
    if (unit == name) return symbol;
  return "";
}

/// "m = 1 kg", "Θ = 40°", "F = sin(t)": a setting with its unit.
std::string fact(const KeySpec& spec, const std::string& value) {
  std::string shown = markup_escaped(value);
  std::string unit = unit_symbol(spec.unit);
  if (spec.kind == ValueKind::number || spec.kind == ValueKind::angle) {
    std::string text = value;
    const bool radians = spec.kind == ValueKind::angle && text.size() > 3 && text.ends_with("rad");
    if (radians) text.resize(text.size() - 3), unit = " rad";
    try {
      char number[32];
      std::snprintf(number, sizeof number, "%.4g", evaluate_constant(spec.name, text));
      shown = number;
    } catch (const UsageError&) {
    }
  }
  const bool tight = unit == "°" || unit.empty() || unit.front() == ' ';
  return key_markup(spec.name) + " = " + shown + (unit.empty() ? "" : tight ? unit : " " + unit);
}
}  // namespace

std::string setting_facts(const Parameters& p, const std::string& except) {
  std::string facts;
  for (const auto& a : p.given_assignments()) {
    const std::string key = a.substr(0, a.find('='));
    if (key == except || is_time_key(key)) continue;
    for (const KeySpec& spec : p.specs())
      if (spec.name == key) facts += (facts.empty() ? "" : render::kCaptionSeparator) + fact(spec, a.substr(a.find('=') + 1));
  }
  return facts;
}

std::string dt_fact(const std::string& model, double dt) {
  std::string time_unit;
  for (const auto& m : all_models())
    if (same_name(m.name, model) && !m.time_unit.empty()) time_unit = " " + m.time_unit;
  char text[64];
  std::snprintf(text, sizeof text, "Δ<i>t</i> = %.4g%s", dt, time_unit.c_str());
  return text;
}

std::string run_caption(const std::string& model, const Parameters& p, const TimeMesh& mesh) {
  std::string caption = setting_facts(p);
  caption += (caption.empty() ? "" : render::kCaptionSeparator) + dt_fact(model, mesh.dt);
  return caption + render::kCaptionSeparator + std::string(scheme_info(mesh.scheme).name);
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
