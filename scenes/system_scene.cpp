// SystemScene: a system's diagram alone or beside stacked panels, the scene of every model.
#include "scenes/system_scene.hpp"

#include <algorithm>
#include <cmath>

#include "render/draw/caption.hpp"
#include "render/draw/text.hpp"
#include "render/labels/label_placer.hpp"

namespace vibra::scenes {

SystemScene::SystemScene(int width, int height, const TrajectoryInfo& info, SceneStyle style,
                         std::unique_ptr<Diagram> diagram, std::vector<QuantityPanelSpec> specs,
                         std::unique_ptr<EnergyBars> bars)
    : height_(height),
      style_(std::move(style)),
      heading_(style_.title, style_.equation, width, height),
      diagram_(std::move(diagram)),
      legend_(diagram_->legend(), height),
      bars_(std::move(bars)),
      background_([this](render::Canvas& c) { draw_static(c); }) {
  const double scale = render::scale_for_height(height);
  // The title and equation take a band across the top; the rest lays out below it.
  const double band = heading_.height();
  std::vector<NoteTarget> targets;
  if (style_.layout == Layout::fbd) {
    diagram_area_ = {0, band, double(width), height - band};
  } else {
    // Energy bars widen the diagram's area by most of their strip, so the
    // diagram keeps its size and the panels give up the room.
    const double bars = bars_ ? bars_->width(scale) : 0;
    const double diagram_width = std::min((bars_ ? 0.54 : 0.46) * width, 1.0 * height + bars);
    diagram_area_ = {0, band, diagram_width, height - band};
    if (specs.empty())
      for (PanelSpec& own : diagram_->panels()) specs.push_back({std::move(own.label), std::move(own.series), {}, {}, {}, 0, {}});
    const double x = diagram_width, w = width - diagram_width - 10 * scale, top = band + 10 * scale;
    const double h = (height - top - 10 * scale) / std::max<size_t>(1, specs.size());
    for (size_t i = 0; i < specs.size(); ++i) {
      targets.push_back({panel_names(i, "", specs[i].label),
                         specs[i].curves.empty() ? std::function<double(std::span<const double>)>() : specs[i].curves.front().value,
                         !specs[i].is_phase()});
      panels_.push_back(make_scene_panel(std::move(specs[i]), info, render::PixelRect{x, top + i * h, w, h}, scale,
                                         style_.window_mode, style_.window));
      if (panels_.back()->against_time()) time_labels_panel_ = i;
    }
  }
  // Room for arrow labels and the read-out at the top; the caption's line at
  // the bottom comes below the lowest arrow's label.
  // A diagram with force arrows keeps a line for its force scale's key above the caption.
  const double key_line = diagram_->force_key() ? 24 * scale : 0;
  const double side = 48 * scale, top = 56 * scale, bottom = (style_.caption.empty() ? 52 : 80) * scale + key_line;
  // Scheme formulas that would take more than 55% of the diagram's part are
  // left out of the legend (the names stay): at 640x360 they would cover the drawing.
  if (legend_.width() > 0.55 * diagram_area_.w) legend_.drop_formulas();
  // A legend too wide for a small frame overlaps the drawing rather than squeeze it away.
  const double view_width = std::max(diagram_area_.w - 2 * side - legend_.width(), 0.3 * diagram_area_.w);
  view_area_ = {diagram_area_.x + side, diagram_area_.y + top, view_width, diagram_area_.h - top - bottom};
  if (bars_) {
    // The bars take a strip at the diagram's right; the arrows' labels keep
    // their margin beside the narrower view.
    const double strip = bars_->width(scale);
    view_area_.w -= strip;
    bars_->place({view_area_.x + view_area_.w + side, diagram_area_.y + 12 * scale, strip - 16 * scale,
                  view_area_.y + view_area_.h + 40 * scale - diagram_area_.y - 12 * scale},
                 scale);
  }
  world_.setEmpty();
  if (!style_.notes.empty())
    notes_.emplace(style_.notes, targets, width, height, info.mesh.T, style_.colors.wire, style_.colors.background.with_alpha(1));
}

void SystemScene::record(std::span<const double> row) {
  diagram_->record(row, world_);
  legend_.record(row);
  if (notes_) notes_->record(row);
  for (auto& panel : panels_) panel->record(row);
  if (bars_) bars_->record(row);
}

void SystemScene::observe(std::span<const double> row) {
  for (auto& panel : panels_) panel->observe(row);
  if (bars_) bars_->observe(row);
}

void SystemScene::record_between(std::span<const double> row) {
  diagram_->record(row, world_);  // the frames show these states too
  if (notes_) notes_->record(row);
  for (auto& panel : panels_) panel->record_between(row);
}

void SystemScene::observe_between(std::span<const double> row) {
  for (auto& panel : panels_) panel->observe_between(row);
}

void SystemScene::look_ahead(std::span<const std::vector<double>> next_samples) {
  for (auto& panel : panels_) panel->look_ahead(next_samples);
  if (bars_) bars_->look_ahead(next_samples);
}

double SystemScene::sample_interval() const {
  double finest = 0;
  for (const auto& panel : panels_)
    if (const double t = panel->time_per_column(); t > 0) finest = finest > 0 ? std::min(finest, t) : t;
  return finest / 2;
}

void SystemScene::prepare() {
  if (view_) return;
  if (!style_.caption.empty()) {
    // A long caption breaks between facts onto up to three lines (or
    // shrinks) to stay inside the diagram's part; the diagram makes room.
    render::Canvas measure = render::Canvas::image(1, height_);
    const double scale = measure.scale();
    // Beside energy bars, the caption stops short of their labels.
    const double room = (bars_ ? bars_->area().x - 8 * scale - diagram_area_.x : diagram_area_.w) - 32 * scale;
    caption_ = render::fit_caption(measure, style_.caption, room,
                                   {15, style_.colors.wire.with_alpha(0.75)}, 3);
    view_area_.h -= caption_->height() - caption_->line_height;
  }
  diagram_->finish_recording(world_);
  // The force key's names (and a long note) take rows above its scale's
  // line (known now: a pendulum without drag names no drag).
  if (const std::optional<ForceKey> key = diagram_->force_key()) {
    render::Canvas measure = render::Canvas::image(1, height_);
    const double width = key_width(measure.scale());
    key_note_row_ = !force_note_fits(measure, *key, render::WorldView(world_, view_area_).zoom(), width);
    view_area_.h -= force_key_rows_height(measure, *key, width, key_note_row_);
  }
  place_legend();
  view_.emplace(world_, view_area_);
  for (auto& panel : panels_) panel->finish_recording();
}

render::WorldView SystemScene::view_at(std::span<const double> row) {
  prepare();
  return view_for(diagram_->view_at(row));
}

render::WorldView SystemScene::view_for(const std::optional<FollowingView>& moving) const {
  return moving ? render::WorldView(moving->centre, moving->sizes, view_area_) : *view_;
}

void SystemScene::draw_static(render::Canvas& canvas) {
  canvas.clear(style_.colors.background);
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i]->draw_static(canvas, i == time_labels_panel_);
  render::DrawingRecord record;
  canvas.record_into(&record);
  heading_.draw(canvas, style_.colors.wire);
  diagram_->draw_static(canvas, *view_);
  if (!legend_.empty()) {
    render::OutlineKindScope kind(canvas, render::OutlineKind::legend);
    legend_.draw_static(canvas, legend_corner(canvas.scale()));
  }
  const double scale = canvas.scale();
  double bottom = diagram_area_.y + diagram_area_.h - 12 * scale;
  if (caption_) {
    render::draw_caption(canvas, {diagram_area_.x + 16 * scale, bottom}, *caption_);
    bottom -= caption_->height() + 8 * scale;
  }
  if (const std::optional<ForceKey> key = diagram_->force_key())
    draw_force_key(canvas, *key, view_->zoom(), {diagram_area_.x + 16 * scale, bottom}, key_width(scale),
                   key_note_row_, style_.colors.wire.with_alpha(0.75));
  canvas.record_into(nullptr);
  static_outline_ = std::move(record.outline);
  static_marks_.reset(static_outline_.shapes().size());
}

void SystemScene::draw(render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.paint(canvas, progress_to(row));
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i]->draw(canvas, row[0], row, i == time_labels_panel_);
  const std::optional<FollowingView> moving = diagram_->view_at(row);
  const render::WorldView view = view_for(moving);
  // Everything in the diagram's part is recorded, so that its labels,
  // placed last, keep off all of it.
  last_frame_ = {};
  last_frame_.outline = static_outline_;
  canvas.record_into(&last_frame_);
  if (moving || !legend_.empty()) {
    // A following view runs its ground off the sides and the bottom, and a
    // comparison's run that blows up leaves the view: keep them out of the
    // panels, the legend, the energy bars and the caption's line.
    cairo_save(canvas.cr());
    const render::PixelRect area = drawing_area();
    const double bottom =
        moving ? std::min(area.y + area.h, view_area_.y + view_area_.h + 16 * canvas.scale()) : area.y + area.h;
    const double right = bars_ ? bars_->area().x - 8 * canvas.scale() : area.x + area.w;
    // At whole pixels: Cairo clips to a pixel-aligned rectangle without a mask.
    const double x0 = std::round(area.x), y0 = std::round(area.y);
    cairo_rectangle(canvas.cr(), x0, y0, std::round(right) - x0, std::round(bottom) - y0);
    cairo_clip(canvas.cr());
    diagram_->draw(canvas, view, row);
    cairo_restore(canvas.cr());
  } else {
    diagram_->draw(canvas, view, row);
  }
  if (!legend_.empty()) {
    render::OutlineKindScope kind(canvas, render::OutlineKind::legend);
    legend_.draw(canvas, legend_corner(canvas.scale()), row[0]);
  }
  if (bars_) bars_->draw(canvas, row);
  draw_readout(canvas, diagram_area_, row[0], style_);
  canvas.record_into(nullptr);
  // Notes are placed after every other label, near the middle of the view.
  if (notes_)
    for (auto& request : notes_->body_requests(row[0], view_area_.center())) last_frame_.labels.push_back(std::move(request));
  last_frame_.placed =
      render::place_labels(canvas, last_frame_.labels, last_frame_.outline, label_area(canvas.scale()), &label_memory_,
                          &static_marks_);
  render::draw_placed_labels(canvas, last_frame_.placed);
  if (notes_)
    notes_->draw_panel_notes(canvas, row[0], [this](size_t i) { return i < panels_.size() ? panels_[i]->time_plot() : nullptr; });
}

void SystemScene::skip(const render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.skip(canvas, progress_to(row));
}

void SystemScene::place_legend() {
  if (legend_.empty() || world_.isEmpty()) return;
  // The legend above the view instead of beside it: the view gets the
  // legend's column back and gives up its rows. Taken when the diagram, fitted
  // to its world box, comes out larger (by a twentieth at least). A
  // comparison has no energy bars, so the column is the view's to take.
  const double scale = render::scale_for_height(height_);
  const double legend_bottom = legend_corner(scale).y() + legend_.height(scale) + 8 * scale;
  render::PixelRect above = view_area_;
  above.w = view_area_.w + legend_.width();
  above.h = view_area_.y + view_area_.h - legend_bottom;
  above.y = legend_bottom;
  if (above.h > 0 && above.w > 0 &&
      render::WorldView(world_, above).zoom() > 1.05 * render::WorldView(world_, view_area_).zoom())
    view_area_ = above, legend_on_top_ = true;
}

render::PixelRect SystemScene::drawing_area() const {
  const double w = legend_on_top_ ? diagram_area_.w
                                  : std::max(diagram_area_.w - legend_.width(), view_area_.x + view_area_.w - diagram_area_.x);
  return {diagram_area_.x, diagram_area_.y, w, diagram_area_.h};
}

render::PixelRect SystemScene::label_area(double scale) const {
  render::PixelRect area = drawing_area();
  if (bars_) area.w = bars_->area().x - 8 * scale - area.x;
  return area;
}

double SystemScene::key_width(double scale) const {
  const double right = bars_ ? bars_->area().x - 8 * scale : diagram_area_.x + diagram_area_.w;
  return right - diagram_area_.x - 32 * scale;
}

render::Point SystemScene::legend_corner(double scale) const {
  return {diagram_area_.x + diagram_area_.w - 4 * scale, diagram_area_.y + 44 * scale};  // below the read-out
}

StaticLayer::Grow SystemScene::progress_to(std::span<const double> row) {
  return [this, now = std::vector<double>(row.begin(), row.end())](LayerGrowth& growth) {
    for (auto& panel : panels_) panel->draw_progress(growth, now);
  };
}

}  // namespace vibra::scenes
