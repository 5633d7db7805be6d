// SeriesPanel: curves against time beside a diagram, following a long run (full or moving window).
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
  marks_.resize(series_.size());
  brackets_.resize(series_.size());
  // The runs' curves, the first (measured) last so that it is on top; then
  // the dashed references over them.
  for (size_t i = series_.size(); i-- > 0;)
    if (!series_[i].dashed) order_.push_back(i);
  for (size_t i = 0; i < series_.size(); ++i)
    if (series_[i].dashed) order_.push_back(i);
}

void SeriesPanel::record(std::span<const double> row) { add_row(row, true); }
void SeriesPanel::record_between(std::span<const double> row) { add_row(row, false); }
void SeriesPanel::observe(std::span<const double> row) {
  for (size_t i = 0; i < series_.size(); ++i)
    if (series_[i].mesh_values && !series_[i].of_time) brackets_[i].observe(row[0], series_[i].value(row));
  add_recent(row, true);
}

void SeriesPanel::look_ahead(std::span<const std::vector<double>> next_samples) {
  // Each run's next sample holds its own columns only: a series takes the
  // first in which it has a value.
  for (size_t i = 0; i < series_.size(); ++i) {
    if (!series_[i].mesh_values || series_[i].of_time) continue;
    brackets_[i].look_ahead(NAN, NAN);
    for (const auto& next : next_samples)
      if (const double v = series_[i].value(next); std::isfinite(v)) {
        brackets_[i].look_ahead(next[0], v);
        break;
      }
  }
}

void SeriesPanel::observe_between(std::span<const double> row) { add_recent(row, false); }

double SeriesPanel::value_drawn(size_t i, double t, std::span<const double> row) const {
  const SeriesSpec& s = series_[i];
  if (s.of_time) return s.of_time(t);
  if (!s.mesh_values) return s.value(row);
  if (const std::optional<double> on_chord = brackets_[i].on_chord(t)) return *on_chord;
  return s.value(row);
}

void SeriesPanel::add_row(std::span<const double> row, bool mesh_row) {
  for (size_t i = 0; i < series_.size(); ++i) {
    const double v = series_[i].value(row);
    if (!std::isfinite(v)) continue;
    if (i == 0) first_curve_seen_ = true;
    lo_ = std::min(lo_, v), hi_ = std::max(hi_, v);
    if (mode_ != WindowMode::whole_run) continue;
    whole_[i].add(row[0], v);
    // At least 6 px apart, so at most a few hundred marks over the run.
    if (mesh_row && marker_radius(i) > 0) marks_[i].emplace_back(row[0], v);
  }
}

void SeriesPanel::add_recent(std::span<const double> row, bool mesh_row) {
  for (size_t i = 0; i < recent_.size(); ++i) {
    if (series_[i].of_time) continue;  // drawn from its function of t
    const double v = series_[i].value(row);
    if (!std::isfinite(v)) continue;
    recent_[i].add(row[0], v);
    if (!mesh_row || marker_radius(i) <= 0) continue;
    // The two windows a frame can show, like the envelope's.
    auto& marks = marks_[i];
    if (!marks.empty() && row[0] < marks.back().first) marks.clear();  // a new pass from the start
    marks.emplace_back(row[0], v);
    const auto old = std::find_if(marks.begin(), marks.end(), [&](const auto& m) { return m.first >= row[0] - 2 * window_; });
    marks.erase(marks.begin(), old);
  }
}

void SeriesPanel::draw_marks(render::Canvas& canvas, size_t i, double from_x, double until_x) const {
  const double radius = marker_radius(i);
  if (radius <= 0 || i >= marks_.size()) return;
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_rectangle(cr, from_x, 0, canvas.width() - from_x, canvas.height());
  cairo_clip(cr);
  for (const auto& [t, v] : marks_[i]) {
    const render::Point p = panel_.to_pixel(t, v);
    if (p.x() > until_x) break;
    if (p.x() >= from_x - radius - 1) render::fill_pixel_disc(canvas, p, radius, series_[i].color);
  }
  cairo_restore(cr);
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

double SeriesPanel::marker_radius(size_t i) const {
  if (!(mesh_dt_ > 0) || series_[i].of_time || !series_[i].mesh_values) return 0;
  const double spacing = mesh_dt_ / window_ * panel_.area().w, scale = panel_.scale();
  return spacing >= kMarkedSpacing * scale ? std::min(3.4 * scale, spacing / 3) : 0;
}

const std::vector<render::GrowingPolyline>& SeriesPanel::whole_curves() const {
  if (!whole_curves_.empty() || mode_ != WindowMode::whole_run) return whole_curves_;
  const int columns = whole_.empty() ? panel_.columns() : whole_[0].columns();
  const double column_width = t_end_ / columns;
  for (size_t i = 0; i < series_.size(); ++i) {
    std::vector<render::Point> points;
    if (series_[i].of_time) {
      // At every half column, on one grid for the whole run: smooth at any dt.
      for (int k = 0; k <= 2 * columns; ++k) {
        const double x = std::min(t_end_, k * column_width / 2), y = series_[i].of_time(x);
        if (std::isfinite(y)) points.push_back(panel_.to_pixel(x, y));
      }
    } else {
      points = whole_[i].polyline(columns - 1, [&](double x, double y) { return panel_.to_pixel(x, y); });
    }
    whole_curves_.emplace_back(std::move(points));
  }
  return whole_curves_;
}

void SeriesPanel::draw_static(render::Canvas& canvas, bool time_labels) const {
  if (mode_ != WindowMode::whole_run) return;
  draw_axes(canvas, time_labels);
}

void SeriesPanel::draw_progress(LayerGrowth& growth, std::span<const double> row) {
  if (mode_ != WindowMode::whole_run || whole_.empty()) return;
  const double t = std::min(row[0], t_end_), until_x = panel_.to_pixel(t, 0).x();
  // Each curve ends where it is at t: its value from the solution at t.
  auto now = [&](size_t i) -> std::optional<render::Point> {
    const double value = value_drawn(i, t, row);
    if (!std::isfinite(value)) return std::nullopt;
    return panel_.to_pixel(t, value);
  };
  // What is on the layer is final left of settled_x_: a frame at the same
  // instant (a pause) adds nothing.
  if (!growth.from_start && until_x <= progress_x_) return;
  const render::PixelRect& area = panel_.area();
  render::Canvas& layer = growth.layer;
  const double reach = render::GrowingPolyline::reach(2.4 * layer.scale());
  // Where every curve still to grow is final: a curve that has ended (a run
  // that left the view) holds nothing back, or every frame after its end
  // would redraw a strip from there, wider and wider.
  double last_x = 1e300;
  for (size_t i = 0; i < series_.size(); ++i)
    if (const auto x = whole_curves()[i].last_x(until_x); x && !whole_curves()[i].complete_until(until_x))
      last_x = std::min(last_x, *x);
  cairo_save(layer.cr());
  render::clip_to_pixels(layer.cr(), area);
  if (growth.from_start) {
    settled_x_ = std::floor(area.x);
    for (size_t i : order_) {
      whole_curves()[i].draw_until(layer, until_x, now(i), {series_[i].color, 2.4, series_[i].dashed});
      draw_marks(layer, i, settled_x_, until_x);  // from the panel's first whole pixel, as every strip after
    }
  } else {
    // The strip from where the curves were last final to past their new end
    // is drawn again, as the still would draw it.
    const double right = std::ceil(until_x + reach);
    growth.reset({settled_x_, std::floor(area.y), right - settled_x_, std::ceil(area.y + area.h) - std::floor(area.y)});
    for (size_t i : order_) {
      whole_curves()[i].draw_piece_until(layer, settled_x_, until_x, now(i), {series_[i].color, 2.4, series_[i].dashed});
      draw_marks(layer, i, settled_x_, until_x);  // clipped to the strip
    }
  }
  cairo_restore(layer.cr());
  if (last_x < 1e300) settled_x_ = std::max(settled_x_, std::floor(last_x - reach));
  progress_x_ = until_x;
}

void SeriesPanel::draw_cursors(render::Canvas& canvas, double t, std::span<const double> row) const {
  // Every run's own cursor, the first (measured) one last, on top: curves
  // that coincide still show each run where it is.
  for (size_t i : order_) {
    if (series_[i].dashed) continue;
    const double value = value_drawn(i, t, row);
    if (!std::isfinite(value)) continue;
    if (i == 0) panel_.draw_cursor(canvas, t, value, series_[i].color);
    else render::fill_pixel_disc(canvas, panel_.to_pixel(t, value), 4 * panel_.scale(), series_[i].color);
  }
}

void SeriesPanel::draw(render::Canvas& canvas, double t, std::span<const double> row, bool time_labels) const {
  if (mode_ == WindowMode::whole_run) return draw_cursors(canvas, t, row);
  const auto [x0, x1] = window_at(t);
  panel_.set_x_range(x0, x1);
  draw_axes(canvas, time_labels);
  if (mode_ == WindowMode::jumps && t < window_ * (1 - 1e-12)) return;  // no window completed yet
  const render::PixelRect& area = panel_.area();
  cairo_save(canvas.cr());
  render::clip_to_pixels(canvas.cr(), area);
  // jumps shows only completed windows; the others draw up to t.
  const double last_x = mode_ == WindowMode::jumps ? x1 : t;
  cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_ROUND);  // no mitre spikes past a coarse run's mesh values
  for (size_t i : order_) {
    const render::Stroke stroke{series_[i].color, 2.4, series_[i].dashed};
    if (series_[i].of_time) {
      panel_.draw_function(canvas, series_[i].of_time, x0, last_x, stroke);
      continue;
    }
    const auto& envelope = recent_[i];
    auto points = envelope.polyline(envelope.column_of(x0), envelope.column_of(last_x) - (mode_ == WindowMode::jumps),
                                    [&](double x, double y) { return panel_.to_pixel(x, y); });
    // On from the last sample to where the curve is at t (the cursor).
    if (const double value = value_drawn(i, t, row); mode_ != WindowMode::jumps && std::isfinite(value)) {
      const render::Point now = panel_.to_pixel(t, value);
      if (points.empty() || now.x() > points.back().x()) points.push_back(now);
    }
    render::draw_pixel_polyline(canvas, points, stroke);
    draw_marks(canvas, i, std::floor(area.x), panel_.to_pixel(last_x, 0).x());
  }
  cairo_restore(canvas.cr());
  if (mode_ != WindowMode::jumps) draw_cursors(canvas, t, row);
}

}  // namespace vibra::scenes
