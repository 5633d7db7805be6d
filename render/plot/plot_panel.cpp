// PlotPanel: a moving time plot with axes, ticks and curves drawn through their pixel-column envelopes.
#include "render/plot/plot_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/draw/text.hpp"
#include "render/plot/axis.hpp"

namespace vibra::render {

namespace {
constexpr double kPanelTickFont = 15, kPanelLabelFont = 19;

double nice_step(double span, int target) {
  const double raw = span / std::max(1, target);
  const double magnitude = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10 * magnitude;
}
/// An axis label followed by its ticks' common factor and offset, if any.
std::string with_common(const std::string& label, const std::string& common) {
  return common.empty() ? label : label + "  <span size=\"smaller\">(" + common + ")</span>";
}
}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double step = nice_step(hi - lo, target);
  // At most a few dozen ticks, whatever the numbers: where the span is below
  // the resolution of lo (a window of 1e-16 at t = 0.5), k * step repeats
  // one value and an unbounded loop would never end.
  const int most = 4 * std::max(1, target) + 4;
  const double first = std::ceil(lo / step - 1e-9);
  for (int i = 0; i < most && (first + i) * step <= hi + 1e-9 * step; ++i) {
    const double tick = (first + i) * step;
    if (!ticks.empty() && !(tick > ticks.back())) break;  // below the resolution of lo: no distinct ticks
    ticks.push_back(tick);
  }
  return ticks;
}

std::string tick_label(double value, double step) {
  if (std::abs(value) < 1e-9 * step) value = 0;
  int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
  // Steps of 2.5 x 10^k need one more digit than their power of ten.
  if (std::abs(std::fmod(step * std::pow(10, decimals), 1.0) - 0.5) < 1e-6) ++decimals;
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s[0] == '-') s = "\u2212" + s.substr(1);  // a real minus sign
  return s;
}

PlotPanel::PlotPanel(const PixelRect& outer, double scale) : outer_(outer), scale_(scale) {
  const double left = 64 * scale, bottom = 34 * scale, top = 30 * scale, right = 26 * scale;
  area_ = {outer.x + left, outer.y + top, std::max(1.0, outer.w - left - right), std::max(1.0, outer.h - top - bottom)};
}

void PlotPanel::set_x_range(double x0, double x1) {
  x0_ = x0;
  x1_ = x1 > x0 ? x1 : x0 + 1;
}

void PlotPanel::set_y_range(double y0, double y1) {
  if (!std::isfinite(y0) || !std::isfinite(y1)) y0 = -1, y1 = 1;
  if (y1 - y0 < 1e-12 * std::max(1.0, std::abs(y0))) {
    const double pad = std::max(1e-3, 0.1 * std::abs(y0));
    y0 -= pad, y1 += pad;
  }
  // A small margin so extremes do not touch the frame; ticks fall inside.
  const double pad = kYMargin * (y1 - y0);
  y0_ = y0 - pad;
  y1_ = y1 + pad;
}

Point PlotPanel::to_pixel(double x, double y) const {
  return {area_.x + (x - x0_) / (x1_ - x0_) * area_.w, area_.y + (y1_ - y) / (y1_ - y0_) * area_.h};
}

void PlotPanel::draw_axes(Canvas& canvas, const std::string& y_label, const std::string& x_label) const {
  const Stroke grid{palette::grid, 1};
  const TextStyle ticks{kPanelTickFont, palette::ink.with_alpha(0.8)};
  // Tiny or huge ranges (a radius drifting by 1e-9) label their ticks in a
  // power of ten and an offset that the axis's label states once.
  const int y_target = tick_target(canvas, true), x_target = tick_target(canvas, false);
  const std::vector<double> y_ticks = nice_ticks(y0_, y1_, y_target), x_ticks = nice_ticks(x0_, x1_, x_target);
  const LinearTickLabels y_labels = linear_tick_labels(y_ticks, nice_step(y1_ - y0_, y_target));
  const LinearTickLabels x_labels = linear_tick_labels(x_ticks, nice_step(x1_ - x0_, x_target));
  for (size_t i = 0; i < y_ticks.size(); ++i) {
    const Point p = to_pixel(x0_, y_ticks[i]);
    draw_pixel_line(canvas, p, {area_.x + area_.w, p.y()}, grid);
    draw_text(canvas, {area_.x - 6 * scale_, p.y()}, y_labels.labels[i], ticks, Anchor::right);
  }
  for (size_t i = 0; i < x_ticks.size(); ++i) {
    const Point p = to_pixel(x_ticks[i], y0_);
    draw_pixel_line(canvas, {p.x(), area_.y}, p, grid);
    if (!x_label.empty()) draw_text(canvas, {p.x(), p.y() + 4 * scale_}, x_labels.labels[i], ticks, Anchor::top);
  }
  if (y0_ < 0 && y1_ > 0) draw_pixel_line(canvas, to_pixel(x0_, 0), to_pixel(x1_, 0), {palette::faint, 1.2});
  cairo_rectangle(canvas.cr(), area_.x, area_.y, area_.w, area_.h);
  cairo_set_source_rgba(canvas.cr(), palette::ink.r, palette::ink.g, palette::ink.b, 0.7);
  cairo_set_line_width(canvas.cr(), 1.2 * scale_);
  canvas.stroke();
  // The y label sits above the frame's top-left corner: readable without
  // rotation, clear of the curve, and it does not steal width from the plot.
  draw_text(canvas, {area_.x, area_.y - 3 * scale_}, y_title(y_label, y_target), {kPanelLabelFont, palette::ink},
            Anchor::bottom_left);
  // The x label sits at the end of the axis, inside the frame, as in textbooks.
  if (!x_label.empty()) {
    TextStyle style{kPanelLabelFont, palette::ink};
    style.halo = true;
    draw_text(canvas, {area_.x + area_.w - 6 * scale_, area_.y + area_.h - 4 * scale_},
              with_common(x_label, x_labels.common), style,
              Anchor::bottom_right);
  }
}

void PlotPanel::draw_envelope(Canvas& canvas, const ColumnEnvelope& envelope, double up_to_x, const Stroke& s) const {
  draw_envelope_columns(canvas, envelope, 0, envelope.column_of(up_to_x), s);
}

void PlotPanel::draw_envelope_columns(Canvas& canvas, const ColumnEnvelope& envelope, int first_column, int last_column,
                                      const Stroke& s) const {
  auto points = envelope.polyline(first_column, last_column, [&](double x, double y) { return to_pixel(x, y); });
  cairo_save(canvas.cr());
  clip_to_pixels(canvas.cr(), area_);
  draw_pixel_polyline(canvas, points, s);
  cairo_restore(canvas.cr());
}

void PlotPanel::draw_function(Canvas& canvas, const std::function<double(double)>& f, double from_x, double to_x,
                              const Stroke& s) const {
  from_x = std::max(from_x, x0_), to_x = std::min(to_x, x1_);
  if (!(to_x > from_x)) return;
  const double step = (x1_ - x0_) / area_.w / 2;  // half a pixel column
  const long long samples = static_cast<long long>(std::ceil((to_x - from_x) / step));
  std::vector<Point> points;
  points.reserve(samples + 1);
  for (long long k = 0; k <= samples; ++k) {
    const double x = std::min(to_x, from_x + k * step);
    const double y = f(x);
    if (std::isfinite(y)) points.push_back(to_pixel(x, y));
  }
  cairo_save(canvas.cr());
  clip_to_pixels(canvas.cr(), area_);
  draw_pixel_polyline(canvas, points, s);
  cairo_restore(canvas.cr());
}

void PlotPanel::draw_cursor(Canvas& canvas, double x, double y, const Color& c) const {
  const Point p = to_pixel(x, y);
  draw_pixel_line(canvas, {p.x(), area_.y}, {p.x(), area_.y + area_.h}, {palette::ink.with_alpha(0.35), 1.2});
  cairo_new_path(canvas.cr());
  cairo_arc(canvas.cr(), p.x(), p.y(), 5 * scale_, 0, 2 * M_PI);
  cairo_set_source_rgba(canvas.cr(), c.r, c.g, c.b, c.a);
  canvas.fill();
}

int PlotPanel::tick_target(Canvas& canvas, bool vertical) const {
  // The most ticks (up to 5 on y, 6 on x) whose labels keep apart: a quarter
  // of a line between them on y, a gap beside the widest label on x. A small
  // panel (320x180) gets fewer ticks rather than labels written over each other.
  const TextStyle style{kPanelTickFont};
  const double lo = vertical ? y0_ : x0_, hi = vertical ? y1_ : x1_;
  const double pixels = vertical ? area_.h : area_.w;
  const int most = vertical ? 5 : 6;
  for (int target = most; target > 2; --target) {
    const double step = nice_step(hi - lo, target);
    const double apart = step / (hi - lo) * pixels;
    double needed = 0;
    if (vertical) {
      needed = 1.25 * text_size(canvas, "0", style).y();
    } else {
      for (const std::string& label : linear_tick_labels(nice_ticks(lo, hi, target), step).labels)
        needed = std::max(needed, text_size(canvas, label, style).x());
      needed += 10 * scale_;
    }
    if (apart >= needed) return target;
  }
  return 2;
}

std::string PlotPanel::y_title(const std::string& y_label, int y_target) const {
  const std::vector<double> ticks = nice_ticks(y0_, y1_, y_target);
  return with_common(y_label, linear_tick_labels(ticks, nice_step(y1_ - y0_, y_target)).common);
}

void PlotPanel::draw_legend(Canvas& canvas, const std::vector<LegendItem>& entries, const std::string& y_label,
                            bool margin_below_free) const {
  const TextStyle style{kPanelTickFont, palette::ink};
  const double sample = 22 * scale_, gap = 6 * scale_, between = 14 * scale_;
  double width = 0, height = 0;
  for (const LegendItem& item : entries) {
    const Point size = text_size(canvas, item.label, style);
    width += size.x() + gap + sample + between;
    height = std::max(height, size.y());
  }
  width -= between;
  const Point title = text_size(canvas, y_title(y_label, tick_target(canvas, true)), {kPanelLabelFont, palette::ink});
  // Outside the plot where there is room, over no data: the title row,
  // right-aligned after the y label; else the margin under the plot when no
  // tick labels take it (a panel stacked above another); else, as a last
  // resort, inside the plot's top-right corner.
  const bool on_title_row = area_.x + title.x() + 2 * between + width <= area_.x + area_.w &&
                            area_.y - 3 * scale_ - std::max(height, title.y()) >= outer_.y - 1;
  const double bottom = area_.y + area_.h;
  const bool under_plot = !on_title_row && margin_below_free && width <= area_.w &&
                          bottom + 4 * scale_ + height <= outer_.y + outer_.h + 1;
  const double centre_y = on_title_row ? area_.y - 3 * scale_ - title.y() / 2
                          : under_plot ? bottom + 4 * scale_ + height / 2
                                       : area_.y + 6 * scale_ + height / 2;
  double x = area_.x + area_.w - (on_title_row || under_plot ? 0 : 8 * scale_);
  for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
    const Point size = text_size(canvas, it->label, style);
    draw_text(canvas, {x, centre_y}, it->label, style, Anchor::right);
    x -= size.x() + gap;
    draw_pixel_line(canvas, {x - sample, centre_y}, {x, centre_y}, {it->color, 2.5, it->dashed});
    x -= sample + between;
  }
}

}  // namespace vibra::render
