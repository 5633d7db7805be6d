#include "scenes/series_panel.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/text.hpp"

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
  std::vector<std::pair<std::string, render::Color>> legend;
  for (const auto& s : series_)
    if (!s.label.empty()) legend.emplace_back(s.label, s.color);
  if (legend.size() > 1) panel_.draw_legend(canvas, legend);
  if (!first_curve_seen_ && !empty_note_.empty()) {
    render::TextStyle style{15, render::palette::ink.with_alpha(0.8)};
    style.halo = true;
    render::draw_text(canvas, panel_.area().center(), empty_note_, style);
  }
}

void SeriesPanel::draw_static(render::Canvas& canvas, bool time_labels) const {
  if (mode_ != WindowMode::whole_run) return;
  draw_axes(canvas, time_labels);
  for (size_t i = 0; i < series_.size(); ++i) {
    const render::Stroke faint{series_[i].color.with_alpha(0.22), 2, series_[i].dashed};
    if (series_[i].of_time)
      panel_.draw_function(canvas, series_[i].of_time, 0, t_end_, faint);
    else
      panel_.draw_envelope(canvas, whole_[i], t_end_, faint);
  }
}

void SeriesPanel::draw_progress(render::Canvas& layer, double t, bool from_start) {
  if (mode_ != WindowMode::whole_run || whole_.empty()) return;
  const int to = whole_[0].column_of(t);
  // One column back, so the new piece joins the old one without a gap.
  const int from = from_start ? 0 : std::max(0, progress_column_ - 1);
  const double column_width = t_end_ / whole_[0].columns();
  for (size_t i = 0; i < series_.size(); ++i) {
    const render::Stroke stroke{series_[i].color, 2.4, series_[i].dashed};
    if (series_[i].of_time)  // to the same column centre as the envelopes
      panel_.draw_function(layer, series_[i].of_time, from * column_width, (to + 0.5) * column_width, stroke);
    else
      panel_.draw_envelope_columns(layer, whole_[i], from, to, stroke);
  }
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
  cairo_rectangle(canvas.cr(), area.x, area.y, area.w, area.h);
  cairo_clip(canvas.cr());
  // jumps shows only completed windows; the others draw up to t.
  const double last_x = mode_ == WindowMode::jumps ? x1 : t;
  for (size_t i = 0; i < series_.size(); ++i) {
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
