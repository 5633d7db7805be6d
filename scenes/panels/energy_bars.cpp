// Energy bars: kinetic, potential, dissipated energy and the work of external forces at one instant.
#include "scenes/panels/energy_bars.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"
#include "render/plot/plot_panel.hpp"

namespace vibra::scenes {

namespace {
/// The integral over [a, b] of the polynomial through the n points (x, y),
/// by 3-point Gauss-Legendre: exact up to degree 5.
double integral_through(const double* x, const double* y, int n, double a, double b) {
  const double nodes[] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, weights[] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  double sum = 0;
  for (int q = 0; q < 3; ++q) {
    const double t = 0.5 * (a + b) + 0.5 * (b - a) * nodes[q];
    double p = 0;  // Lagrange's form: n is at most 4
    for (int i = 0; i < n; ++i) {
      double l = 1;
      for (int j = 0; j < n; ++j)
        if (j != i) l *= (t - x[j]) / (x[i] - x[j]);
      p += l * y[i];
    }
    sum += weights[q] * p;
  }
  return 0.5 * (b - a) * sum;
}
}  // namespace

double ForcingWork::beyond_newest(double t, double power) const {
  if (kept_ == 0 || !(t > ts_[kept_ - 1])) return 0;
  // The newest three samples and (t, power); at the run's opening, all of
  // them from the first, so that the opening is as accurate as the rest.
  const int first = opening_ ? 0 : kept_ - 3;
  double x[4], y[4];
  int n = 0;
  for (int i = first; i < kept_; ++i, ++n) x[n] = ts_[i], y[n] = ps_[i];
  x[n] = t, y[n] = power;
  return opening_ ? integral_through(x, y, n + 1, ts_[0], t) - W_ : integral_through(x, y, n + 1, ts_[kept_ - 1], t);
}

void ForcingWork::add(double t, double power) {
  if (kept_ > 0 && t < ts_[kept_ - 1]) kept_ = 0, W_ = 0, opening_ = true;  // a new pass from the start
  if (kept_ > 0 && t == ts_[kept_ - 1]) return;
  W_ += beyond_newest(t, power);
  if (kept_ == 4) {  // past the opening: keep the newest three
    std::copy(ts_ + 1, ts_ + 4, ts_), std::copy(ps_ + 1, ps_ + 4, ps_);
    kept_ = 3;
  }
  ts_[kept_] = t, ps_[kept_] = power, ++kept_;
  if (kept_ == 4) opening_ = false;
}

double ForcingWork::at(double t, double power) const { return W_ + beyond_newest(t, power); }

namespace {
constexpr double kTitle = 40, kLabels = 38;  // heights of the title and the labels, 720p pixels
const char* const kNames[] = {"kinetic", "potential", "dissipated", "work of F"};
const render::Color kColors[] = {render::palette::orange, render::palette::blue, render::palette::faint,
                                 render::palette::purple};

/// A unit as typeset: "length^2" with a superscript.
std::string unit_markup(std::string unit) {
  for (size_t at; (at = unit.find('^')) != std::string::npos && at + 1 < unit.size();)
    unit.replace(at, 2, "<sup>" + unit.substr(at + 1, 1) + "</sup>");
  return unit;
}
}  // namespace

EnergyBars::EnergyBars(const TrajectoryInfo& info)
    : energy_(info.energy), power_(info.forcing_power), unit_(unit_markup(info.energy_unit)) {
  if (!energy_) throw UsageError("this model has no mechanical energy to show: drop --energy-bars");
}

EnergyBudget EnergyBars::budget(std::span<const double> row, const ForcingWork& work) const {
  const EnergyParts E = energy_(row);
  const double W = power_ ? work.at(row[0], power_(row)) : 0;
  return {E.kinetic, E.potential, E0_ + W - E.total(), W};
}

void EnergyBars::record(std::span<const double> row) {
  if (std::isnan(E0_)) E0_ = energy_(row).total();
  if (power_) pre_pass_work_.add(row[0], power_(row));
  for (double v : values(budget(row, pre_pass_work_)))
    if (std::isfinite(v)) lo_ = std::min(lo_, v), hi_ = std::max(hi_, v);
}

void EnergyBars::observe(std::span<const double> row) {
  if (power_) work_.add(row[0], power_(row));
  const std::array<double, 4> parts = values(budget(row, work_));
  for (size_t k = 0; k < parts.size(); ++k) brackets_[k].observe(row[0], parts[k]);
}

void EnergyBars::look_ahead(std::span<const std::vector<double>> next_samples) {
  // The bars are of one run (a comparison has none): its next sample, if any.
  const std::array<double, 4> parts =
      next_samples.size() == 1 ? values(budget(next_samples[0], work_)) : std::array<double, 4>{NAN, NAN, NAN, NAN};
  const double t = next_samples.size() == 1 ? next_samples[0][0] : NAN;
  for (size_t k = 0; k < parts.size(); ++k) brackets_[k].look_ahead(t, parts[k]);
}

EnergyBudget EnergyBars::at(std::span<const double> row) const {
  std::array<double, 4> parts = values(budget(row, work_));
  for (size_t k = 0; k < parts.size(); ++k)
    if (const std::optional<double> on_chord = brackets_[k].on_chord(row[0])) parts[k] = *on_chord;
  return {parts[0], parts[1], parts[2], parts[3]};
}

void EnergyBars::place(const render::PixelRect& area, double scale) { area_ = area, scale_ = scale; }

render::PixelRect EnergyBars::bars_area() const {
  const double s = scale_;
  return {area_.x, area_.y + kTitle * s, area_.w, std::max(1.0, area_.h - (kTitle + kLabels) * s)};
}

double EnergyBars::pixel_y(const render::PixelRect& bars, double value) const {
  // 4% headroom: a frame between steps may hold a little more than any step.
  const double span = hi_ - lo_ > 0 ? 1.04 * (hi_ - lo_) : 1;
  return std::clamp(bars.y + (lo_ + span - value) / span * bars.h, bars.y, bars.y + bars.h);
}

EnergyBars::BarPixels EnergyBars::bar_pixels(std::span<const double> row) const {
  const render::PixelRect bars = bars_area();
  const std::array<double, 4> v = values(at(row));
  BarPixels out;
  for (int i = 0; i < this->bars(); ++i) {
    const double y = pixel_y(bars, std::isfinite(v[i]) ? v[i] : 0), zero = pixel_y(bars, 0);
    out.top[i] = std::min(y, zero), out.bottom[i] = std::max(y, zero);
  }
  return out;
}

void EnergyBars::draw(render::Canvas& canvas, std::span<const double> row) const {
  const double s = scale_;
  const render::PixelRect& area = area_;
  const render::PixelRect bars = bars_area();
  const BarPixels px = bar_pixels(row);
  const int n = this->bars();
  const double pitch = bars.w / n, bar_w = 0.55 * pitch;
  const render::Color ink = render::palette::ink;
  render::draw_text(canvas, {area.x + area.w, area.y}, "energy", {16, ink}, render::Anchor::top_right);
  render::draw_text(canvas, {area.x + area.w, area.y + 20 * s}, unit_, {13, ink.with_alpha(0.75)}, render::Anchor::top_right);
  // The fixed scale: faint lines at round values, the zero line darker.
  const std::vector<double> ticks = render::nice_ticks(lo_, hi_, 3);
  for (double v : ticks) render::draw_pixel_line(canvas, {bars.x, pixel_y(bars, v)}, {bars.x + bars.w, pixel_y(bars, v)}, {render::palette::grid, 1});
  cairo_t* cr = canvas.cr();
  for (int i = 0; i < n; ++i) {
    const double cx = bars.x + (i + 0.5) * pitch;
    cairo_rectangle(cr, cx - bar_w / 2, px.top[i], bar_w, std::max(0.0, px.bottom[i] - px.top[i]));
    cairo_set_source_rgba(cr, kColors[i].r, kColors[i].g, kColors[i].b, 0.9);
    canvas.fill();
    // Labels alternate between two lines so that neighbours never touch,
    // each under its bar but never past the strip's ends.
    const render::TextStyle style{14, ink};
    const double half = 0.5 * render::text_size(canvas, kNames[i], style).x();
    const double x = std::clamp(cx, area.x + half, std::max(area.x + half, area.x + area.w - half));
    render::draw_text(canvas, {x, bars.y + bars.h + (4 + (i % 2) * 18) * s}, kNames[i], style, render::Anchor::top);
  }
  render::draw_pixel_line(canvas, {bars.x, pixel_y(bars, 0)}, {bars.x + bars.w, pixel_y(bars, 0)}, {ink.with_alpha(0.7), 1.2});
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1;
  render::TextStyle label{13, ink.with_alpha(0.8)};
  label.halo = true;
  for (double v : ticks)
    render::draw_text(canvas, {bars.x, pixel_y(bars, v) - 1 * s}, render::tick_label(v, step), label, render::Anchor::bottom_left);
}

}  // namespace vibra::scenes
