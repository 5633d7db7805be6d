#include "scenes/system_scene.hpp"

#include <algorithm>

#include "render/caption.hpp"
#include "render/text.hpp"

namespace vibra::scenes {

SystemScene::SystemScene(int width, int height, double t_end, SceneStyle style, std::unique_ptr<Diagram> diagram)
    : height_(height),
      style_(std::move(style)),
      diagram_(std::move(diagram)),
      background_([this](render::Canvas& c) { draw_static(c); }) {
  const double scale = render::scale_for_height(height);
  if (style_.layout == Layout::fbd) {
    diagram_area_ = {0, 0, double(width), double(height)};
  } else {
    const double diagram_width = std::min(0.46 * width, 1.0 * height);
    diagram_area_ = {0, 0, diagram_width, double(height)};
    std::vector<PanelSpec> specs = diagram_->panels();
    const double x = diagram_width, w = width - diagram_width - 10 * scale, top = 10 * scale;
    const double h = (height - top - 10 * scale) / std::max<size_t>(1, specs.size());
    for (size_t i = 0; i < specs.size(); ++i)
      panels_.emplace_back(render::PixelRect{x, top + i * h, w, h}, scale, std::move(specs[i].label),
                           std::move(specs[i].series), t_end, style_.window_mode, style_.window);
  }
  // Room for arrow labels and the read-out at the top; the caption's line at
  // the bottom comes below the lowest arrow's label.
  const double side = 48 * scale, top = 56 * scale, bottom = (style_.caption.empty() ? 52 : 80) * scale;
  view_area_ = {diagram_area_.x + side, diagram_area_.y + top, diagram_area_.w - 2 * side,
                diagram_area_.h - top - bottom};
  world_.setEmpty();
}

void SystemScene::record(std::span<const double> row) {
  diagram_->record(row, world_);
  for (auto& panel : panels_) panel.record(row);
}

void SystemScene::observe(std::span<const double> row) {
  for (auto& panel : panels_) panel.observe(row);
}

void SystemScene::prepare() {
  if (view_) return;
  if (!style_.caption.empty()) {
    // A long caption breaks between facts onto up to three lines (or
    // shrinks) to stay inside the diagram's part; the diagram makes room.
    render::Canvas measure = render::Canvas::image(1, height_);
    const double scale = measure.scale();
    caption_ = render::fit_caption(measure, style_.caption, diagram_area_.w - 32 * scale,
                                   {15, style_.colors.wire.with_alpha(0.75)}, 3);
    view_area_.h -= caption_->height() - caption_->line_height;
  }
  diagram_->finish_recording(world_);
  view_.emplace(world_, view_area_);
  for (auto& panel : panels_) panel.finish_recording();
}

render::WorldView SystemScene::view_at(std::span<const double> row) {
  prepare();
  if (std::optional<WorldBox> moving = diagram_->view_at(row)) return render::WorldView(*moving, view_area_);
  return *view_;
}

void SystemScene::draw_static(render::Canvas& canvas) {
  canvas.clear(style_.colors.background);
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw_static(canvas, i + 1 == panels_.size());
  diagram_->draw_static(canvas, *view_);
  if (caption_)
    render::draw_caption(
        canvas, {diagram_area_.x + 16 * canvas.scale(), diagram_area_.y + diagram_area_.h - 12 * canvas.scale()},
        *caption_);
}

void SystemScene::draw(render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.paint(canvas, progress_to(row[0]));
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw(canvas, row[0], row, i + 1 == panels_.size());
  const std::optional<WorldBox> moving = diagram_->view_at(row);
  const render::WorldView view = moving ? render::WorldView(*moving, view_area_) : *view_;
  if (moving) {
    // A following view runs its ground off the sides and the bottom: keep it
    // out of the panels and off the caption's line.
    cairo_save(canvas.cr());
    const double bottom = std::min(diagram_area_.y + diagram_area_.h, view_area_.y + view_area_.h + 16 * canvas.scale());
    cairo_rectangle(canvas.cr(), diagram_area_.x, diagram_area_.y, diagram_area_.w, bottom - diagram_area_.y);
    cairo_clip(canvas.cr());
    diagram_->draw(canvas, view, row);
    cairo_restore(canvas.cr());
  } else {
    diagram_->draw(canvas, view, row);
  }
  draw_readout(canvas, diagram_area_, row[0], style_);
}

void SystemScene::skip(const render::Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.skip(canvas, progress_to(row[0]));
}

StaticLayer::Grow SystemScene::progress_to(double t) {
  return [this, t](render::Canvas& layer, bool from_start) {
    for (auto& panel : panels_) panel.draw_progress(layer, t, from_start);
  };
}

}  // namespace vibra::scenes
