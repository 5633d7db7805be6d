// The legend of a comparison's runs, in a column of its own at the right of the diagram.
#include "scenes/overlays/run_legend.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"
#include "render/typeset/formula_draw.hpp"
#include "render/typeset/formula_layout.hpp"
#include "scenes/diagrams/comparison_labels.hpp"

namespace vibra::scenes {

namespace {
constexpr double kLabelSize = 16, kNoteSize = 13, kFormulaSize = 15, kFormulaGap = 4;
constexpr double kSwatch = 26, kGap = 8, kRow = 24, kNoteRow = 18;

std::string note_text(EarlyEnd end, double t) { return early_end_note(end, t); }
}  // namespace

RunLegend::RunLegend(std::vector<LegendEntry> entries, int height)
    : entries_(std::move(entries)), blow_up_times_(entries_.size(), INFINITY), ends_(entries_.size(), EarlyEnd::none) {
  if (entries_.empty()) return;
  render::Canvas measure = render::Canvas::image(8, height);
  const double scale = measure.scale();
  double widest = render::text_size(measure, note_text(EarlyEnd::left_view, 1e-300), {kNoteSize}).x();
  for (const auto& e : entries_) widest = std::max(widest, render::text_size(measure, e.label, {kLabelSize}).x());
  names_width_ = widest + (kSwatch + kGap + 12) * scale;
  for (const auto& e : entries_) {
    formulas_.emplace_back();
    if (e.formula.empty()) continue;
    formulas_.back() = render::layout_formula(measure, render::parse_formula(e.formula), {kFormulaSize});
    widest = std::max(widest, formulas_.back()->width);
  }
  width_ = widest + (kSwatch + kGap + 12) * scale;
}

void RunLegend::drop_formulas() {
  for (auto& formula : formulas_) formula.reset();
  width_ = names_width_;
}

void RunLegend::record(std::span<const double> row) {
  for (size_t i = 0; i < entries_.size(); ++i) {
    const LegendEntry& e = entries_[i];
    if (ends_[i] != EarlyEnd::none || !e.probe || std::isfinite(e.probe(row))) continue;
    // A run between its own samples reads NaN too (Trajectory::hide_runs_between_their_samples):
    // where the run says how it ended, only an early end counts.
    const EarlyEnd end = e.early_end ? e.early_end() : EarlyEnd::blew_up;
    if (end == EarlyEnd::none) continue;
    blow_up_times_[i] = row[0];
    ends_[i] = end;
  }
}

double RunLegend::row_top(size_t i, double scale) const {
  // A note row under each earlier entry that blows up.
  double y = 0;
  for (size_t k = 0; k < i; ++k) {
    y += (kRow + (std::isfinite(blow_up_times_[k]) ? kNoteRow : 0)) * scale;
    if (formulas_[k]) y += formulas_[k]->height() + 2 * kFormulaGap * scale;
  }
  return y;
}

void RunLegend::draw_static(render::Canvas& canvas, const render::Point& corner) const {
  const double scale = canvas.scale();
  const double left = corner.x() - width_ + 12 * scale;
  for (size_t i = 0; i < entries_.size(); ++i) {
    const LegendEntry& e = entries_[i];
    const double y = corner.y() + row_top(i, scale) + 0.5 * kRow * scale;
    render::draw_pixel_line(canvas, {left, y}, {left + kSwatch * scale, y}, {e.color, 3, e.dashed});
    render::draw_text(canvas, {left + (kSwatch + kGap) * scale, y}, e.label, {kLabelSize}, render::Anchor::left);
    if (formulas_[i])
      render::draw_math(canvas, *formulas_[i],
                        {left + (kSwatch + kGap) * scale, y + (0.5 * kRow + kFormulaGap) * scale + formulas_[i]->ascent},
                        {e.color.with_alpha(1)}, e.formula);
  }
}

void RunLegend::draw(render::Canvas& canvas, const render::Point& corner, double t) const {
  const double scale = canvas.scale();
  const double left = corner.x() - width_ + (12 + kSwatch + kGap) * scale;
  for (size_t i = 0; i < entries_.size(); ++i) {
    const LegendEntry& e = entries_[i];
    if (!(t >= blow_up_times_[i])) continue;
    const double y = corner.y() + row_top(i, scale) + (kRow + 0.5 * kNoteRow) * scale +
                     (formulas_[i] ? formulas_[i]->height() + 2 * kFormulaGap * scale : 0);
    render::draw_text(canvas, {left, y}, note_text(ends_[i], blow_up_times_[i]), {kNoteSize, e.color}, render::Anchor::left);
  }
}

}  // namespace vibra::scenes
