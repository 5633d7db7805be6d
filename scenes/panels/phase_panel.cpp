// PhasePanel: the phase plane of a run, fixed ranges from the pre-pass and a trail.
#include "scenes/panels/phase_panel.hpp"

#include <algorithm>
#include <cmath>

#include "render/draw/polyline/simplified_polyline.hpp"

namespace vibra::scenes {

PhasePanel::PhasePanel(const render::PixelRect& outer, double scale, std::string x_label, std::string y_label,
                       std::vector<PhaseCurveSpec> curves, double trail)
    : panel_(outer, scale),
      x_label_(std::move(x_label)),
      y_label_(std::move(y_label)),
      curves_(std::move(curves)),
      trail_(trail > 0 ? trail : 1),
      trails_(curves_.size()) {}

void PhasePanel::record(std::span<const double> row) {
  for (const auto& c : curves_) {
    const double x = c.x(row), y = c.y(row);
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    x_lo_ = std::min(x_lo_, x), x_hi_ = std::max(x_hi_, x);
    y_lo_ = std::min(y_lo_, y), y_hi_ = std::max(y_hi_, y);
  }
}

void PhasePanel::observe(std::span<const double> row) {
  const double t = row[0];
  // At most kTrailPoints over the trail's duration: a point only when enough
  // time has passed since the last one kept.
  const double spacing = trail_ / kTrailPoints;
  for (size_t i = 0; i < curves_.size(); ++i) {
    auto& trail = trails_[i];
    if (!trail.empty() && t < trail.back().t) trail.clear();  // a new pass from the start
    if (!trail.empty() && t - trail.back().t < spacing) continue;
    const double x = curves_[i].x(row), y = curves_[i].y(row);
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    trail.push_back({t, x, y});
    while (trail.size() > 1 && trail.front().t < t - trail_) trail.pop_front();
    while (trail.size() > kTrailPoints + 1) trail.pop_front();
  }
}

void PhasePanel::finish_recording() {
  if (x_lo_ > x_hi_) x_lo_ = -1, x_hi_ = 1, y_lo_ = -1, y_hi_ = 1;
  if (x_hi_ - x_lo_ < 1e-12 * std::max(1.0, std::abs(x_lo_))) x_lo_ -= 1e-3, x_hi_ += 1e-3;
  // Both ranges get the same margin a side: x's here, y's from set_y_range.
  constexpr double kMargin = render::PlotPanel::kYMargin;
  const double pad = kMargin * (x_hi_ - x_lo_);
  double x0 = x_lo_ - pad, x1 = x_hi_ + pad, y0 = y_lo_, y1 = y_hi_;
  if (equal_scales_) {
    // The larger of the two units per pixel for both, each range widened
    // about its middle; y's is given short of its margin, which set_y_range adds.
    const render::PixelRect& area = panel_.area();
    const double per_pixel = std::max((x1 - x0) / area.w, (1 + 2 * kMargin) * (y1 - y0) / area.h);
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1), y_half = 0.5 * per_pixel * area.h / (1 + 2 * kMargin);
    x0 = xm - 0.5 * per_pixel * area.w, x1 = xm + 0.5 * per_pixel * area.w;
    y0 = ym - y_half, y1 = ym + y_half;
  }
  panel_.set_x_range(x0, x1);
  panel_.set_y_range(y0, y1);
}

void PhasePanel::draw_static(render::Canvas& canvas, bool) const {
  panel_.draw_axes(canvas, y_label_, x_label_);
  std::vector<render::PlotPanel::LegendItem> legend;
  for (const auto& c : curves_)
    if (!c.label.empty()) legend.push_back({c.label, c.color});
  if (legend.size() > 1) panel_.draw_legend(canvas, legend, y_label_);
}

void PhasePanel::draw(render::Canvas& canvas, double t, std::span<const double> row, bool) const {
  const render::PixelRect& area = panel_.area();
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  render::clip_to_pixels(cr, area);
  // Butt ends: the polylines of two fade steps meet at a shared point, where
  // round ends would overlap into a darker dot.
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cr, 2.4 * canvas.scale());
  for (size_t i = 0; i < curves_.size(); ++i) {
    const render::Color& c = curves_[i].color;
    const double x = curves_[i].x(row), y = curves_[i].y(row);
    // The trail up to the frame's time (the solver may have stepped past it),
    // ending at the current point; older pieces are fainter.
    std::vector<TrailPoint> points;
    for (const auto& p : trails_[i])
      if (p.t < t && p.t >= t - trail_) points.push_back(p);
    if (std::isfinite(x) && std::isfinite(y)) points.push_back({t, x, y});
    // The fading is in kFadeSteps steps: the pieces of one step are one
    // polyline, stroked once (not one stroke for each of up to kTrailPoints
    // pieces, which made a three-run comparison's frames cost twice a single
    // run's). Sixteen steps of a 2.4-pixel line look as smooth as 32, and a
    // stroke costs about as much for its setup as for its length.
    constexpr double kFadeSteps = 16;
    auto fade = [&](size_t k) {
      const double age = (t - points[k].t) / trail_;
      return std::round(std::clamp(1 - age, 0.05, 1.0) * kFadeSteps) / kFadeSteps;
    };
    std::vector<render::Point> piece;
    for (size_t k = 1; k < points.size();) {
      const double alpha = fade(k);
      piece.assign(1, panel_.to_pixel(points[k - 1].x, points[k - 1].y));
      for (; k < points.size() && fade(k) == alpha; ++k) piece.push_back(panel_.to_pixel(points[k].x, points[k].y));
      // Only the points the picture needs: a smooth piece sampled every
      // step strokes as a few segments.
      cairo_new_path(cr);
      for (size_t j : render::simplified_polyline(piece.size(), [&](size_t i) { return piece[i]; }, 0.25))
        cairo_line_to(cr, piece[j].x(), piece[j].y());
      cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a * alpha);
      canvas.stroke();
    }
    if (std::isfinite(x) && std::isfinite(y)) {
      const render::Point p = panel_.to_pixel(x, y);
      cairo_new_path(cr);
      cairo_arc(cr, p.x(), p.y(), 5.5 * canvas.scale(), 0, 2 * M_PI);
      cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
      canvas.fill();
    }
  }
  cairo_restore(cr);
}

}  // namespace vibra::scenes
