#include "scenes/panels/series_panel.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/draw/text.hpp"

namespace vibra::scenes {

WindowMode parse_window_mode(const std::string& text) {
  if (text == "drawing") return WindowMode::drawing;
  if (text == "movement") return WindowMode::movement;
  if (text == "jumps") return WindowMode::jumps;
  throw UsageError("window mode '" + text + "' is not one of drawing, movement, jumps");
}

SeriesPanel::SeriesPanel(const render::PixelRect& outer, double scale, std::string y_label,
                         std::vector<SeriesSpec> series, double t_end, WindowMode mode, double window)
    : panel_(outer, scale),
      y_label_(std::move(y_label)),
      series_(std::move(series)),
      t_end_(t_end),
      mode_(mode),
      window_(mode == WindowMode::whole_run ? t_end : window) {
  const int columns = panel_.columns();
  for (size_t i = 0; i < series_.size(); ++i) {
    if (mode_ == WindowMode::whole_run)
      whole_.emplace_back(columns, 0, t_end_);
    else  // two windows: jumps shows the last complete one while the next fills
      recent_.emplace_back(window_ / columns, 2 * columns + 2);
  }
  panel_.set_x_range(0, window_);
}

void SeriesPanel::record(std::span<const double> row) {
  for (size_t i = 0; i < series_.size(); ++i) {
    const double v = series_[i].value(row);
    if (!std::isfinite(v)) continue;
    if (i == 0) first_curve_seen_ = true;
    lo_ = std::min(lo_, v), hi_ = std::max(hi_, v);
    if (mode_ == WindowMode::whole_run) whole_[i].add(row[0], v);
  }
}

void SeriesPanel::observe(std::span<const double> row) {
  for (size_t i = 0; i < recent_.size(); ++i) {
    if (series_[i].of_time) continue;  // drawn from its function of t
    if (const double v = series_[i].value(row); std::isfinite(v)) recent_[i].add(row[0], v);
  }
}

void SeriesPanel::finish_recording() {
  // A known function's extremes fall between steps too: sample it finely.
  const int samples = 4 * panel_.columns();
  for (const auto& s : series_)
    if (s.of_time)
      for (int k = 0; k <= samples; ++k) {
        const double v = s.of_time(t_end_ * k / samples);
        if (std::isfinite(v)) lo_ = std::min(lo_, v), hi_ = std::max(hi_, v);
      }
  if (lo_ > hi_) lo_ = -1, hi_ = 1;
  if (hi_ - lo_ < least_span_) {
    const double middle = 0.5 * (lo_ + hi_);
    lo_ = middle - 0.5 * least_span_, hi_ = middle + 0.5 * least_span_;
  }
  panel_.set_y_range(lo_, hi_);
}

std::pair<double, double> SeriesPanel::window_at(double t) const {
  const double k = std::floor(t / window_ * (1 + 1e-12));
  switch (mode_) {
    case WindowMode::whole_run: return {0, t_end_};
    case WindowMode::drawing: return {k * window_, (k + 1) * window_};
    case WindowMode::movement: return {std::max(0.0, t - window_), std::max(window_, t)};
    case WindowMode::jumps: return {std::max(0.0, (k - 1) * window_), std::max(window_, k * window_)};
  }
  return {0, window_};
}

void SeriesPanel::draw_axes(render::Canvas& canvas, bool time_labels) const {
  panel_.draw_axes(canvas, y_label_, time_labels ? "<i>t</i>" : "");
  std::vector<render::PlotPanel::LegendItem> legend;
  for (const auto& s : series_)
    if (!s.label.empty()) legend.push_back({s.label, s.color, s.dashed});
  if (legend.size() > 1) panel_.draw_legend(canvas, legend, y_label_, !time_labels);
  if (!first_curve_seen_ && !empty_note_.empty()) {
    render::TextStyle style{15, render::palette::ink.with_alpha(0.8)};
    style.halo = true;
    render::draw_text(canvas, panel_.area().center(), empty_note_, style);
  }
}

const std::vector<render::GrowingPolyline>& SeriesPanel::whole_curves() const {
  if (!whole_curves_.empty() || mode_ != WindowMode::whole_run) return whole_curves_;
  const int columns = whole_.empty() ? panel_.columns() : whole_[0].columns();
  const double column_width = t_end_ / columns;
  for (size_t i = 0; i < series_.size(); ++i) {
    std::vector<render::Point> points;
    std::vector<int> ends(columns);
    if (series_[i].of_time) {
      // At every half column, on one grid for the whole run: column c holds
      // samples 2c and 2c + 1, as an envelope's column holds the samples
      // whose x falls in it.
      for (int k = 0; k <= 2 * columns; ++k) {
        const double x = std::min(t_end_, k * column_width / 2), y = series_[i].of_time(x);
        if (std::isfinite(y)) points.push_back(panel_.to_pixel(x, y));
        ends[std::min(k / 2, columns - 1)] = int(points.size());
      }
    } else {
      const render::ColumnEnvelope& envelope = whole_[i];
      for (int c = 0; c < columns; ++c) {
        const auto column = envelope.polyline(c, c, [&](double x, double y) { return panel_.to_pixel(x, y); });
        points.insert(points.end(), column.begin(), column.end());
        ends[c] = int(points.size());
      }
    }
    whole_curves_.emplace_back(std::move(points), std::move(ends));
  }
  return whole_curves_;
}

void SeriesPanel::draw_static(render::Canvas& canvas, bool time_labels) const {
  if (mode_ != WindowMode::whole_run) return;
  draw_axes(canvas, time_labels);
  const render::PixelRect& area = panel_.area();
  cairo_save(canvas.cr());
  render::clip_to_pixels(canvas.cr(), area);
  // Backwards: the first curve (the measured one) on top of the references.
  for (size_t i = series_.size(); i-- > 0;)
    whole_curves()[i].draw_through(canvas, panel_.columns(), {series_[i].color.with_alpha(0.22), 2, series_[i].dashed});
  cairo_restore(canvas.cr());
}

void SeriesPanel::draw_progress(LayerGrowth& growth, double t) {
  if (mode_ != WindowMode::whole_run || whole_.empty()) return;
  const int to = whole_[0].column_of(t);
  // The whole run's columns are known from the pre-pass, so a column once
  // drawn is complete: frames that stay in it (slow motion) add nothing.
  if (!growth.from_start && to <= progress_column_) return;
  const render::PixelRect& area = panel_.area();
  render::Canvas& layer = growth.layer;
  const double reach = render::GrowingPolyline::reach(2.4 * layer.scale());
  // Where every curve still to grow is final: a curve that has ended (a run
  // that left the view) holds nothing back, or every frame after its end
  // would redraw a strip from there, wider and wider.
  double last_x = 1e300;
  for (size_t i = 0; i < series_.size(); ++i)
    if (const auto x = whole_curves()[i].last_x(to); x && !whole_curves()[i].complete_through(to))
      last_x = std::min(last_x, *x);
  cairo_save(layer.cr());
  render::clip_to_pixels(layer.cr(), area);
  if (growth.from_start) {
    settled_x_ = std::floor(area.x);
    // Backwards: the first curve (the measured one) on top of the references.
    for (size_t i = series_.size(); i-- > 0;)
      whole_curves()[i].draw_through(layer, to, {series_[i].color, 2.4, series_[i].dashed});
  } else {
    // The strip from where the curves were last final to past their new end
    // is drawn again, as the still would draw it.
    const double right = std::ceil(panel_.to_pixel((to + 1.0) * t_end_ / whole_[0].columns(), 0).x() + reach);
    growth.reset({settled_x_, std::floor(area.y), right - settled_x_, std::ceil(area.y + area.h) - std::floor(area.y)});
    // Backwards: the first curve (the measured one) on top of the references.
    for (size_t i = series_.size(); i-- > 0;)
      whole_curves()[i].draw_piece(layer, settled_x_, to, {series_[i].color, 2.4, series_[i].dashed});
  }
  cairo_restore(layer.cr());
  if (last_x < 1e300) settled_x_ = std::max(settled_x_, std::floor(last_x - reach));
  progress_column_ = to;
}

void SeriesPanel::draw(render::Canvas& canvas, double t, std::span<const double> row, bool time_labels) const {
  const double cursor = series_[0].value(row);
  if (mode_ == WindowMode::whole_run) {
    if (std::isfinite(cursor)) panel_.draw_cursor(canvas, t, cursor, series_[0].color);
    return;
  }
  const auto [x0, x1] = window_at(t);
  panel_.set_x_range(x0, x1);
  draw_axes(canvas, time_labels);
  if (mode_ == WindowMode::jumps && t < window_ * (1 - 1e-12)) return;  // no window completed yet
  const render::PixelRect& area = panel_.area();
  cairo_save(canvas.cr());
  render::clip_to_pixels(canvas.cr(), area);
  // jumps shows only completed windows; the others draw up to t.
  const double last_x = mode_ == WindowMode::jumps ? x1 : t;
  // Backwards: the first curve (the measured one) on top of the references.
  for (size_t i = series_.size(); i-- > 0;) {
    if (series_[i].of_time) {
      panel_.draw_function(canvas, series_[i].of_time, x0, last_x, {series_[i].color, 2.4, series_[i].dashed});
      continue;
    }
    const auto& envelope = recent_[i];
    auto points = envelope.polyline(envelope.column_of(x0), envelope.column_of(last_x) - (mode_ == WindowMode::jumps),
                                    [&](double x, double y) { return panel_.to_pixel(x, y); });
    render::draw_pixel_polyline(canvas, points, {series_[i].color, 2.4, series_[i].dashed});
  }
  cairo_restore(canvas.cr());
  if (mode_ != WindowMode::jumps && std::isfinite(cursor)) panel_.draw_cursor(canvas, t, cursor, series_[0].color);
}

}  // namespace vibra::scenes
