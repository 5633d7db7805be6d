// PlotScene: moving plots without a diagram (layouts plot and grid), stacked on one time axis.
#include "scenes/figures/plot_scene.hpp"

#include "scenes/panels/plot_panels.hpp"

#include <algorithm>

#include "render/draw/caption.hpp"
#include "render/draw/text.hpp"

namespace vibra::scenes {

PanelSpec main_quantity_panel(const SceneStyle& style, const std::string& quantity, std::function<double(double)> exact,
                              const std::string& exact_label) {
  const double f = display_factor(quantity);
  const std::string symbol = quantity_symbol(quantity);
  PanelSpec panel{quantity_markup(quantity),
                  {{symbol + " numerical", style.colors.bob, [f](std::span<const double> row) { return f * row[1]; }}}};
  if (exact)
    panel.series.push_back({symbol + " " + exact_label, style.colors.gravity,
                            [exact, f](std::span<const double> row) { return f * exact(row[0]); }, true,
                            [exact, f](double t) { return f * exact(t); }});
  return panel;
}

PlotScene::PlotScene(int width, int height, const TrajectoryInfo& info, SceneStyle style, std::vector<PanelSpec> panels,
                     std::vector<LegendEntry> legend)
    : style_(std::move(style)),
      heading_(style_.title, style_.equation, width, height),
      area_{0, heading_.height(), double(width), height - heading_.height()},
      legend_(std::move(legend), height),
      background_([this](render::Canvas& canvas) { draw_static(canvas); }) {
  const double scale = render::scale_for_height(height), t_end = info.mesh.T;
  const double top = area_.y + 44 * scale, bottom = 30 * scale;
  const double w = width - 10 * scale - legend_.width();
  const double h = (height - top - bottom) / std::max<size_t>(1, panels.size());
  std::vector<NoteTarget> targets;
  for (size_t i = 0; i < panels.size(); ++i)
    targets.push_back({panel_names(i, panels[i].name, panels[i].label),
                       panels[i].series.empty() ? std::function<double(std::span<const double>)>() : panels[i].series.front().value});
  if (!style_.notes.empty()) {
    // Without a diagram, a note with no panel named goes to the first panel.
    std::vector<Note> notes = style_.notes;
    for (Note& note : notes)
      if (note.panel.empty() && !targets.empty()) note.panel = "1";
    notes_.emplace(notes, targets, width, height, t_end, style_.colors.wire, style_.colors.background.with_alpha(1));
  }
  for (size_t i = 0; i < panels.size(); ++i) {
    panels_.emplace_back(render::PixelRect{0, top + i * h, w, h}, scale, std::move(panels[i].label),
                         std::move(panels[i].series), t_end, style_.window_mode, style_.window);
    panels_.back().set_least_span(panels[i].least_span);
    panels_.back().mark_mesh_points(fixed_mesh_step(info));
    panels_.back().set_empty_note(std::move(panels[i].empty_note));
  }
}

void PlotScene::record(std::span<const double> row) {
  for (auto& panel : panels_) panel.record(row);
  legend_.record(row);
  if (notes_) notes_->record(row);
}

void PlotScene::observe(std::span<const double> row) {
  for (auto& panel : panels_) panel.observe(row);
}

void PlotScene::record_between(std::span<const double> row) {
  for (auto& panel : panels_) panel.record_between(row);
  if (notes_) notes_->record(row);
}

void PlotScene::observe_between(std::span<const double> row) {
  for (auto& panel : panels_) panel.observe_between(row);
}

void PlotScene::look_ahead(std::span<const std::vector<double>> next_samples) {
  for (auto& panel : panels_) panel.look_ahead(next_samples);
}

double PlotScene::sample_interval() const {
  double finest = 0;
  for (const auto& panel : panels_)
    if (const double t = panel.time_per_column(); t > 0) finest = finest > 0 ? std::min(finest, t) : t;
  return finest / 2;
}

void PlotScene::prepare() {
  if (prepared_) return;
  for (auto& panel : panels_) panel.finish_recording();
  prepared_ = true;
}

void PlotScene::draw_static(render::Canvas& canvas) {
  canvas.clear(style_.colors.background);
  heading_.draw(canvas, style_.colors.wire);
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw_static(canvas, i + 1 == panels_.size());
  if (!legend_.empty()) legend_.draw_static(canvas, {area_.w - 4 * canvas.scale(), area_.y + 44 * canvas.scale()});
  if (!style_.caption.empty())  // one line under the time axis: shrunk, or cut short, to the width
    render::draw_caption(canvas, {16 * canvas.scale(), area_.y + area_.h - 6 * canvas.scale()},
                         render::fit_caption(canvas, style_.caption, area_.w - 32 * canvas.scale(),
                                             {15, style_.colors.wire.with_alpha(0.75)}, 1));
}

StaticLayer::Grow PlotScene::progress_to(std::span<const double> row) {
  return [this, now = std::vector<double>(row.begin(), row.end())](LayerGrowth& growth) {
    for (auto& panel : panels_) panel.draw_progress(growth, now);
  };
}

void PlotScene::skip(const render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.skip(canvas, progress_to(row));
}

void PlotScene::draw(render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.paint(canvas, progress_to(row));
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw(canvas, row[0], row, i + 1 == panels_.size());
  if (!legend_.empty()) legend_.draw(canvas, {area_.w - 4 * canvas.scale(), area_.y + 44 * canvas.scale()}, row[0]);
  // The read-out sits top right: the panel's y label is top left.
  draw_readout(canvas, {area_.w * 0.55, area_.y, area_.w * 0.45, 40}, row[0], style_);
  if (notes_)
    notes_->draw_panel_notes(canvas, row[0], [this](size_t i) { return i < panels_.size() ? &panels_[i].plot() : nullptr; });
}

}  // namespace vibra::scenes
