#include "scenes/pendulum_scene.hpp"

#include <cmath>
#include <cstdio>

#include "render/shapes.hpp"
#include "render/text.hpp"

namespace vibra::scenes {

using render::Anchor;
using render::Canvas;
using render::Color;
using render::PixelRect;
using render::Stroke;
using render::TextStyle;

namespace {
std::string format(const char* pattern, double a) {
  char buf[128];
  std::snprintf(buf, sizeof buf, pattern, a);
  return buf;
}

std::string magnification_label(double m) {
  if (m == 1) return "<i>D</i>";
  return "<i>D</i> \u00d7" + format(m == std::round(m) ? "%.0f" : "%g", m);
}

PendulumState state_of(std::span<const double> row) { return {row[0], row[1], row[2], row[3], row[4]}; }
}  // namespace

void draw_readout(Canvas& canvas, const PixelRect& area, double t, const SceneStyle& style) {
  const double scale = canvas.scale();
  std::string readout = "<i>t</i> = " + format("%.2f", t);
  if (style.period > 0) readout += format("   (%.2f periods)", t / style.period);
  draw_text(canvas, {area.x + 16 * scale, area.y + 14 * scale}, readout, {20, style.colors.wire}, Anchor::top_left);
}

PendulumScene::PendulumScene(int width, int height, double t_end, SceneStyle style, PendulumDiagramOptions diagram)
    : height_(height), style_(std::move(style)), diagram_(diagram), background_([this](Canvas& c) { draw_static(c); }) {
  const double scale = render::scale_for_height(height);
  if (style_.layout == Layout::fbd) {
    diagram_area_ = {0, 0, double(width), double(height)};
  } else {
    const double diagram_width = std::min(0.46 * width, 1.0 * height);
    diagram_area_ = {0, 0, diagram_width, double(height)};
    const double x = diagram_width, w = width - diagram_width - 10 * scale, top = 10 * scale;
    const double h = (height - top - 10 * scale) / 3;
    const auto& c = style_.colors;
    struct Panel {
      const char* label;
      Color color;
      int column;
      double factor;
    };
    // theta is shown in degrees, the forces in units of m g.
    const Panel specs[] = {{"<i>θ</i> (degrees)", c.bob, 1, 180 / M_PI},
                           {"<i>S</i> / <i>mg</i>  wire force", c.wire_force, 3, 1},
                           {"<i>D</i> / <i>mg</i>  air drag", c.drag, 4, 1}};
    for (int i = 0; i < 3; ++i) {
      const Panel p = specs[i];
      SeriesSpec series{"", p.color, [p](std::span<const double> row) { return p.factor * row[p.column]; }};
      panels_.emplace_back(PixelRect{x, top + i * h, w, h}, scale, p.label, std::vector<SeriesSpec>{series}, t_end,
                           style_.window_mode, style_.window);
    }
  }
  world_.setEmpty();
}

void PendulumScene::record(std::span<const double> row) {
  const PendulumGeometry g = pendulum_geometry(state_of(row), diagram_);
  const double r = diagram_.bob_radius;
  for (const Point& p : {Point(g.bob + Point(r, r)), Point(g.bob - Point(r, r)), g.gravity_tip, g.wire_force_tip,
                         g.drag_tip})
    world_.extend(p);
  for (auto& panel : panels_) panel.record(row);
}

void PendulumScene::observe(std::span<const double> row) {
  for (auto& panel : panels_) panel.observe(row);
}

void PendulumScene::prepare() {
  if (view_) return;
  // The ceiling, the dashed vertical and the angle label always fit.
  world_.extend(Point(-0.35, 0.12));
  world_.extend(Point(0.35, -diagram_.vertical_length));
  const double scale = render::scale_for_height(height_);
  // Room for arrow labels and the read-out lines at the top and bottom; the
  // caption's line at the bottom comes below the lowest arrow's label.
  const double side = 48 * scale, top = 56 * scale, bottom = (style_.caption.empty() ? 52 : 80) * scale;
  view_.emplace(world_, PixelRect{diagram_area_.x + side, diagram_area_.y + top, diagram_area_.w - 2 * side,
                                  diagram_area_.h - top - bottom});
  for (auto& panel : panels_) panel.finish_recording();
}

void PendulumScene::draw_static(Canvas& canvas) {
  canvas.clear(style_.colors.background);
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw_static(canvas, i + 1 == panels_.size());
  draw_ceiling(canvas, *view_, Point::Zero(), 0.3, {style_.colors.wire, 2.2});
  if (!style_.caption.empty())
    draw_text(canvas, {diagram_area_.x + 16 * canvas.scale(), diagram_area_.y + diagram_area_.h - 12 * canvas.scale()},
              style_.caption, {15, style_.colors.wire.with_alpha(0.75)}, Anchor::bottom_left);
}

void PendulumScene::draw(Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.paint(canvas, progress_to(row[0]));
  for (size_t i = 0; i < panels_.size(); ++i) panels_[i].draw(canvas, row[0], row, i + 1 == panels_.size());
  draw_diagram(canvas, state_of(row));
  draw_readout(canvas, diagram_area_, row[0], style_);
}

void PendulumScene::skip(const Canvas& canvas, std::span<const double> row) {
  prepare();
  background_.skip(canvas, progress_to(row[0]));
}

StaticLayer::Grow PendulumScene::progress_to(double t) {
  return [this, t](Canvas& layer, bool from_start) {
    for (auto& panel : panels_) panel.draw_progress(layer, t, from_start);
  };
}

void PendulumScene::draw_diagram(Canvas& canvas, const PendulumState& state) {
  const auto& o = diagram_;
  const auto& c = style_.colors;
  const render::WorldView& view = *view_;
  const PendulumGeometry g = pendulum_geometry(state, o);
  const double scale = canvas.scale();

  draw_line(canvas, view, g.pivot, g.vertical_end, {c.wire.with_alpha(0.6), 1.6, true});
  draw_line(canvas, view, g.pivot, g.bob, {c.wire, 2.2});
  draw_arc(canvas, view, g.pivot, o.arc_radius, g.arc_from, g.arc_to, {c.wire, 1.6});
  draw_circle(canvas, view, g.bob, o.bob_radius, c.bob, {c.wire, 1.6});

  struct Force {
    Point tip;
    Color color;
    std::string label;
    bool label_beside;  ///< beside the shaft instead of beyond the tip
  };
  // S runs along the wire toward the pivot, where a label beyond its tip
  // would sit on the wire and the angle arc: it goes beside the shaft instead.
  const Force forces[] = {{g.gravity_tip, c.gravity, "<i>mg</i>", false},
                          {g.wire_force_tip, c.wire_force, "<i>S</i>", true},
                          {g.drag_tip, c.drag, magnification_label(o.drag_magnification), false}};
  const Point bob = view.to_pixel(g.bob);
  const Point outward(std::cos(state.theta), -std::sin(state.theta));  // i_theta in pixels (y down)
  const double side = state.theta >= 0 ? 1 : -1;                       // away from the vertical and the arc
  for (const Force& f : forces) {
    const Point tip = view.to_pixel(f.tip);
    // A vanishing force (drag at a turning point) gets neither arrow nor a label on the bob.
    if ((tip - bob).norm() < 8 * scale) continue;
    draw_arrow(canvas, view, g.bob, f.tip, {f.color, 4.2}, 22);
    TextStyle style{24, f.color};
    style.halo = true, style.halo_color = c.background;
    const Point size = text_size(canvas, f.label, style);
    const Point at = f.label_beside ? render::label_beyond(0.5 * (bob + tip), side * outward, size, 8 * scale)
                                    : render::label_beyond(tip, tip - bob, size, 5 * scale);
    draw_text(canvas, at, f.label, style);
  }

  // The angle's label goes last, over the arrows, with a halo.
  if (std::abs(state.theta) > 0.02) {
    TextStyle label{24, c.wire};
    label.halo = true, label.halo_color = c.background;
    const Point at = view.to_pixel(g.pivot + o.arc_radius * g.theta_label_direction);
    const Point direction(g.theta_label_direction.x(), -g.theta_label_direction.y());
    const std::string theta = "<i>θ</i>";
    draw_text(canvas, render::label_beyond(at, direction, text_size(canvas, theta, label), 4 * scale), theta, label);
  }
}

}  // namespace vibra::scenes
