// A render's notes as callouts: near the diagram's body, or in a panel with an arrow to its curve.
#include "scenes/overlays/note_callouts.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "render/draw/text.hpp"
#include "render/labels/label_placer.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/formula_parser.hpp"
#include "scenes/overlays/note_room.hpp"

namespace vibra::scenes {

namespace {

/// Greek letters as their names, so a panel labelled θ answers to theta.
std::string latin(const std::string& text) {
  static const std::pair<const char*, const char*> kNames[] = {
      {"α", "alpha"}, {"β", "beta"},   {"γ", "gamma"}, {"δ", "delta"}, {"θ", "theta"}, {"λ", "lambda"},
      {"μ", "mu"},    {"ω", "omega"},  {"φ", "phi"},   {"ψ", "psi"},   {"Δ", "Delta"}, {"Θ", "Theta"},
      {"′", "'"},     {"−", "-"},      {"Ω", "Omega"}, {"σ", "sigma"}, {"τ", "tau"},   {"ρ", "rho"}};
  std::string out = text;
  for (const auto& [greek, name] : kNames)
    for (size_t at = 0; (at = out.find(greek, at)) != std::string::npos;) out.replace(at, std::string(greek).size(), name);
  return out;
}
}  // namespace

std::vector<std::string> panel_names(size_t index, const std::string& given, const std::string& label_markup) {
  std::vector<std::string> names = {std::to_string(index + 1)};
  if (!given.empty()) names.push_back(given);
  const std::string plain = render::markup_plain_text(label_markup);
  const size_t end = plain.find_first_of(" (/");
  std::string first = latin(plain.substr(0, end));
  if (!first.empty()) names.push_back(first);
  return names;
}

NoteCallouts::NoteCallouts(const std::vector<Note>& notes, const std::vector<NoteTarget>& targets, int width,
                           int height, double t_end, render::Color ink, render::Color card)
    : targets_(targets),
      courses_(targets.size()),
      next_sample_(targets.size(), -INFINITY),
      pointed_at_(targets.size(), false),
      ink_(ink),
      card_(card) {
  render::Canvas measure = render::Canvas::image(1, height);
  // Longer notes break between words. A card in a panel takes at most a
  // third of the frame's width; one near the diagram's body a fifth, so that
  // it fits beside the body's arrows and wire rather than across them (a
  // third-wide card could only be placed over the pendulum's mg arrow).
  const double panel_room = std::max(kNoteCard.least_room * measure.scale(), width / 3.0);
  const double body_room = std::max(kNoteCard.least_room * measure.scale(), width / 5.0);
  sample_every_ = std::isfinite(t_end) && t_end > 0 ? t_end / 600 : 0;
  for (const Note& note : notes) {
    throw_if_stop_requested();  // each note is typeset: their number is the input's
    Callout c;
    c.note = note;
    c.box = std::make_shared<const render::MathBox>(
        render::layout_rich_text(measure, render::parse_rich_text(note.text), {kNoteCard.text},
                                 note.panel.empty() ? body_room : panel_room));
    if (!note.panel.empty()) {
      std::string known;
      for (size_t i = 0; i < targets.size() && c.target < 0; ++i) {
        if (std::find(targets[i].names.begin(), targets[i].names.end(), note.panel) != targets[i].names.end())
          c.target = int(i);
        // Its name as asked for (--panels error), else its label's first word.
        const auto& names = targets[i].names;
        known += (known.empty() ? "" : ", ") + (names.size() > 1 ? names[1] : names.front());
      }
      if (targets.empty())
        throw UsageError("note '" + quoted_value(note.text, 40) + " @" + quoted_value(note.panel, 20) +
                         "' points at a panel, and this layout has none: drop @" + quoted_value(note.panel, 20) +
                         ", or render with --layout fbd+plot");
      if (c.target < 0)
        throw UsageError("note '" + quoted_value(note.text, 40) + "' points at @" + quoted_value(note.panel, 20) +
                         ", which is no panel here: choose one of " + known + " (or its number, 1 to " +
                         std::to_string(targets.size()) + ")");
      if (!targets[c.target].against_time)
        throw UsageError("note @" + quoted_value(note.panel, 20) +
                         " points at a phase plot: notes point at a curve against time; choose another panel");
    }
    if (c.target >= 0) pointed_at_[size_t(c.target)] = true;
    notes_.push_back(std::move(c));
  }
}

void NoteCallouts::record(std::span<const double> row) {
  const double t = row[0];
  for (Callout& c : notes_) {
    if (c.target < 0) continue;
    const double distance = std::abs(t - c.note.from);
    if (distance < c.nearest) {
      const double v = targets_[c.target].value(row);
      if (std::isfinite(v)) c.value = v, c.nearest = distance;
    }
  }
  for (size_t i = 0; i < targets_.size(); ++i) {
    if (t < next_sample_[i] || !targets_[i].against_time || !pointed_at_[i]) continue;
    const double v = targets_[i].value(row);
    if (std::isfinite(v)) courses_[i].emplace_back(t, v);
    next_sample_[i] = t + sample_every_;
  }
}

render::LabelRequest NoteCallouts::request(const Callout& c, const render::Point& anchor) const {
  render::LabelRequest r;
  r.markup = c.note.text;
  r.style.color = ink_;
  r.style.halo_color = card_;
  r.anchor = anchor;
  r.typeset = c.box;
  return r;
}

std::vector<render::LabelRequest> NoteCallouts::body_requests(double t, const render::Point& anchor) const {
  std::vector<render::LabelRequest> out;
  for (const Callout& c : notes_) {
    if (c.target >= 0 || !c.note.shown_at(t)) continue;
    render::LabelRequest r = request(c, anchor);
    r.direction = render::Point(0, -1);
    r.gap = 12;
    r.leader = render::LabelRequest::Leader::none;
    out.push_back(std::move(r));
  }
  return out;
}

void NoteCallouts::draw_panel_notes(render::Canvas& canvas, double t,
                                    const std::function<const render::PlotPanel*(size_t)>& panel) const {
  for (const Callout& c : notes_) {
    if (c.target < 0 || !c.note.shown_at(t)) continue;
    throw_if_stop_requested();  // each placed in its panel: as many as the input shows at once
    const render::PlotPanel* plot = panel(size_t(c.target));
    if (!plot) continue;
    const render::PixelRect& area = plot->area();
    auto clamped = [&](const render::Point& p) {
      return render::Point(std::clamp(p.x(), area.x, area.x + area.w), std::clamp(p.y(), area.y, area.y + area.h));
    };
    // Off the curve: its course over the run is what the card keeps clear of.
    render::Outline curve;
    const auto& course = courses_[size_t(c.target)];
    std::vector<render::Point> pixels;
    for (const render::Point& tv : course)
      if (tv.x() >= plot->x0() && tv.x() <= plot->x1()) pixels.push_back(clamped(plot->to_pixel(tv.x(), tv.y())));
    cairo_t* cr = canvas.cr();
    cairo_save(cr);  // the outline is made with the canvas's context, which draws nothing here
    cairo_set_line_width(cr, 3 * canvas.scale());
    cairo_new_path(cr);
    for (const render::Point& p : pixels) cairo_line_to(cr, p.x(), p.y());
    if (pixels.size() > 1) curve.add_stroke(cr, render::OutlineKind::drawing);
    cairo_new_path(cr);
    cairo_restore(cr);
    render::LabelRequest r = request(c, clamped(plot->to_pixel(c.note.from, c.value)));
    // Up and to the right of the point, where the curve has not been yet.
    r.direction = render::Point(1, -1);
    r.gap = 28 * canvas.scale();
    r.leader = render::LabelRequest::Leader::arrow;
    render::draw_placed_labels(canvas, render::place_labels(canvas, {r}, curve, area));
  }
}

}  // namespace vibra::scenes
