// The figures of `vibra analyze`, one per experiment of the chapter.
#include "scenes/figures/analysis_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/analysis/fd_accuracy.hpp"
#include "core/analysis/frequency/numerical_frequency.hpp"

namespace vibra::scenes {

namespace {
using render::AxisScale;
using render::PanelOptions;
using render::SeriesStyle;

render::Color series_color(size_t k) { return render::palette::series(k); }

SeriesStyle data_style(size_t k) { return {series_color(k), 2, false, true}; }
SeriesStyle reference_style() { return {render::palette::ink.with_alpha(0.75), 1.8, true, false}; }

PanelOptions log_log(std::string y_label, std::string x_label) {
  return {std::move(y_label), std::move(x_label), AxisScale::logarithmic, AxisScale::logarithmic};
}

PanelOptions linear(std::string y_label, std::string x_label) {
  return {std::move(y_label), std::move(x_label), AxisScale::linear, AxisScale::linear};
}

std::string number(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}
}  // namespace

render::Figure convergence_figure(const std::vector<ModelConvergence>& studies, const std::string& title, int width,
                                  int height) {
  render::Figure figure(width, height, title);
  PanelOptions options = log_log("<i>E</i>, discrete L<sub>2</sub> error", "Δ<i>t</i>");
  for (const auto& level : studies.front().levels) options.x_ticks.push_back(level.dt);
  const int panel = figure.add_panel(options);
  const bool compare = studies.size() > 1;
  for (size_t k = 0; k < studies.size(); ++k) {
    const ModelConvergence& study = studies[k];
    const auto& levels = study.levels;
    const std::string last_rate = levels.size() > 1 ? number("%.2f", levels.back().rate) : "";
    render::Series& errors =
        figure.add_points(panel, (compare ? study.scheme + ": " : "<i>E</i>, ") + "last rate " + last_rate, data_style(k));
    for (const auto& level : levels) errors.add(level.dt, level.error);
    // The reference slope runs parallel to the data at half its height, so both stay visible.
    const ConvergenceLevel& finest = levels.back();
    const double c = 0.5 * finest.error / std::pow(finest.dt, study.order);
    SeriesStyle style = reference_style();
    if (compare) style.color = series_color(k).with_alpha(0.75);
    render::Series& slope = figure.add_points(
        panel, "slope " + std::to_string(study.order) + ", the order of " + study.scheme, style);
    slope.add(levels.front().dt, c * std::pow(levels.front().dt, study.order));
    slope.add(finest.dt, c * std::pow(finest.dt, study.order));
  }
  return figure;
}

render::Figure energy_figure(const std::vector<EnergyError>& table, int width, int height) {
  std::vector<double> Ts, dts;
  std::vector<std::string> schemes;
  auto add_new = [](auto& list, const auto& value) {
    if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
  };
  for (const auto& e : table) add_new(Ts, e.T), add_new(dts, e.dt), add_new(schemes, e.scheme);
  render::Figure figure(width, height,
                        "Energy error of <i>u</i>'' + (2π)<sup>2</sup><i>u</i> = 0, <i>u</i>(0) = 1, <i>u</i>'(0) = 0");
  for (double T : Ts) {
    PanelOptions options = log_log("max |<i>e<sub>E</sub></i>| / <i>E</i>(0) up to <i>T</i> = " + number("%g", T), "Δ<i>t</i>");
    options.x_ticks = dts;
    const int panel = figure.add_panel(options);
    for (size_t k = 0; k < schemes.size(); ++k) {
      // One legend, on the first panel: the colours are the same in all.
      render::Series& s = figure.add_points(panel, panel == 0 ? schemes[k] : "", data_style(k));
      for (const auto& e : table)
        if (e.T == T && e.scheme == schemes[k]) s.add(e.dt, e.max_relative_error);
    }
  }
  return figure;
}

render::Figure empirical_figure(const std::vector<LabelledCycles>& runs, double reference_w,
                                const std::string& reference_label, const std::string& title, int width, int height) {
  render::Figure figure(width, height, title);
  const int frequency = figure.add_panel(linear("angular frequency 2π / <i>p<sub>i</sub></i>", "<i>i</i>"));
  const int amplitude = figure.add_panel(linear("amplitude <i>a<sub>i</sub></i>", "<i>i</i>"));
  int last_i = 0;
  for (size_t k = 0; k < runs.size(); ++k) {
    render::Series& w = figure.add_points(frequency, runs[k].label, data_style(k));
    render::Series& a = figure.add_points(amplitude, "", data_style(k));
    for (const auto& c : runs[k].cycles) {
      w.add(c.i, 2 * M_PI / c.period);
      a.add(c.i, c.amplitude);
      last_i = std::max(last_i, c.i);
    }
  }
  if (reference_w > 0) {
    render::Series& line = figure.add_points(frequency, reference_label, reference_style());
    line.add(0, reference_w);
    line.add(last_i, reference_w);
  }
  return figure;
}

render::Figure frequency_figure(double w, int width, int height) {
  render::Figure figure(width, height,
                        "Numerical frequency of the centered scheme, <i>ω</i> = " + number("%g", w));
  const double limit = 2 / w;
  const int by_dt = figure.add_panel(
      {"angular frequency", "Δ<i>t</i>, up to the stability limit 2/<i>ω</i>", AxisScale::linear, AxisScale::linear, false, std::make_pair(0.0, limit)});
  render::Series& exact = figure.add_curve(by_dt, "<i>ω̃</i> = (2/Δ<i>t</i>) asin(<i>ω</i>Δ<i>t</i>/2) (1.18)",
                                           {series_color(0), 2.4}, 0, limit);
  render::Series& series = figure.add_curve(by_dt, "<i>ω</i>(1 + <i>ω</i><sup>2</sup>Δ<i>t</i><sup>2</sup>/24) (1.19)",
                                            {series_color(1), 2.2, true}, 0, limit);
  const int samples = 400;
  for (int i = 1; i <= samples; ++i) {
    const double dt = limit * i / samples;
    exact.add(dt, numerical_frequency(w, dt));
    series.add(dt, numerical_frequency_series(w, dt));
  }
  render::Series& reference = figure.add_points(by_dt, "<i>ω</i>", reference_style());
  reference.add(0, w);
  reference.add(limit, w);

  // Relative error against steps per period N_P = 2 pi / (w dt), from the limit (pi) to 1000.
  const int by_steps = figure.add_panel(log_log("<i>ω̃</i>/<i>ω</i> − 1", "steps per period <i>N</i><sub>P</sub>"));
  render::Series& exact_error = figure.add_points(by_steps, "(1.18)", {series_color(0), 2.4});
  render::Series& series_error = figure.add_points(by_steps, "(1.19)", {series_color(1), 2.2, true});
  for (int i = 0; i <= samples; ++i) {
    const double steps = M_PI * std::pow(1000 / M_PI, double(i) / samples), dt = 2 * M_PI / (w * steps);
    exact_error.add(steps, numerical_frequency(w, std::min(dt, limit)) / w - 1);
    series_error.add(steps, numerical_frequency_series(w, dt) / w - 1);
  }
  return figure;
}

render::Figure fd_accuracy_figure(int width, int height) {
  render::Figure figure(width, height, "Accuracy of the centered difference for <i>u</i>″ (Exercise 1.8)");
  const int panel = figure.add_panel({"<i>E</i>(<i>p</i>) = [<i>D<sub>t</sub>D<sub>t</sub> u</i>]/<i>u</i>″",
                                      "<i>p</i> = <i>ω</i>Δ<i>t</i>", AxisScale::linear, AxisScale::linear, false,
                                      std::make_pair(0.0, M_PI)});
  render::Series& exact = figure.add_curve(panel, "4 sin<sup>2</sup>(<i>p</i>/2)/<i>p</i><sup>2</sup>",
                                           {series_color(0), 2.4}, 0, M_PI);
  render::Series& taylor = figure.add_curve(
      panel, "1 − <i>p</i><sup>2</sup>/12 + <i>p</i><sup>4</sup>/360", {series_color(1), 2.2, true}, 0, M_PI);
  const int samples = 400;
  for (int i = 0; i <= samples; ++i) {
    const double p = M_PI * i / samples;
    exact.add(p, fd_accuracy(p));
    taylor.add(p, fd_accuracy_taylor(p));
  }
  return figure;
}

render::Figure amplitude_figure(const std::vector<LabelledCycles>& runs, double I, const std::string& title, int width,
                                int height) {
  render::Figure figure(width, height, title);
  const int ratio = figure.add_panel(
      {"<i>a<sub>i</sub></i> / <i>I</i>", "<i>t</i>", AxisScale::linear, AxisScale::logarithmic});
  std::vector<size_t> close;  // schemes that stay within 10% of I: worth a linear close-up
  for (size_t k = 0; k < runs.size(); ++k) {
    render::Series& s = figure.add_points(ratio, runs[k].label, data_style(k));
    double worst = 0;
    for (const auto& c : runs[k].cycles) {
      s.add(c.t, c.amplitude / I);
      worst = std::max(worst, std::abs(c.amplitude - I));
    }
    if (!runs[k].cycles.empty() && worst < 0.1 * std::abs(I)) close.push_back(k);
  }
  if (!close.empty()) {
    const int error = figure.add_panel(linear("<i>a<sub>i</sub></i> − <i>I</i> (schemes within 10%)", "<i>t</i>"));
    for (size_t k : close) {
      render::Series& s = figure.add_points(error, "", data_style(k));
      for (const auto& c : runs[k].cycles) s.add(c.t, c.amplitude - I);
    }
  }
  return figure;
}

render::Figure orbit_figure(const std::vector<OrbitRun>& runs, const std::vector<OrbitRun>& long_runs,
                            const std::vector<Line>& long_fits, const std::string& title, int width, int height) {
  render::Figure figure(width, height, title);
  const long long orbits = runs.empty() || runs[0].blocks.empty() ? 0 : runs[0].blocks.back().orbits;
  PanelOptions options = log_log("max |position error| over " + std::to_string(orbits) + " orbits", "steps per orbit");
  for (const auto& run : runs) options.x_ticks.push_back(run.steps_per_orbit);
  const int by_steps = figure.add_panel(options);
  render::Series& errors = figure.add_points(by_steps, "", data_style(0));
  for (const auto& run : runs) errors.add(run.steps_per_orbit, run.max_error);
  if (long_runs.empty()) return figure;
  const long long block = long_runs[0].blocks.front().orbits;
  const int phase = figure.add_panel(
      linear("angle error atan2(<i>y</i>, <i>x</i>) − <i>t</i> (rad), PEFRL; dashed: least-squares lines", "orbits"));
  const int energy = figure.add_panel({"max |<i>E</i> − <i>E</i>(0)| per block of " + std::to_string(block) + " orbits",
                                       "orbits", AxisScale::linear, AxisScale::logarithmic});
  for (size_t k = 0; k < long_runs.size(); ++k) {
    const OrbitRun& run = long_runs[k];
    const render::Color color = series_color(k + 1);
    const std::string name = std::to_string(run.steps_per_orbit) + " steps/orbit";
    render::Series& data = figure.add_points(
        phase, name + ": " + number("%.2g", long_fits[k].slope) + " rad per orbit", {color, 2, false, true});
    render::Series& energies = figure.add_points(energy, name, {color, 2, false, true});
    for (const auto& b : run.blocks) data.add(b.orbits, b.phase), energies.add(b.orbits, b.energy_error);
    render::Series& fit = figure.add_points(phase, "", {color.with_alpha(0.8), 1.6, true});
    fit.add(0, long_fits[k](0));
    fit.add(run.blocks.back().orbits, long_fits[k](run.blocks.back().orbits));
  }
  return figure;
}

render::Figure period_figure(const std::vector<MeasuredPeriod>& periods, double exact_period,
                             double small_oscillation_period, const std::string& title, int width, int height) {
  render::Figure figure(width, height, title);
  const int panel = figure.add_panel(linear("period <i>P<sub>i</sub></i>", "<i>i</i>"));
  render::Series& measured = figure.add_points(panel, "measured between upward zero crossings", data_style(0));
  for (const auto& p : periods) measured.add(p.i, p.period);
  const double last = periods.empty() ? 1 : std::max(1, periods.back().i);
  auto line = [&](double value, const std::string& label, SeriesStyle style) {
    render::Series& s = figure.add_points(panel, label + " " + number("%.6g", value), style);
    s.add(0, value);
    s.add(last, value);
  };
  if (exact_period > 0) line(exact_period, "exact", {render::palette::vermillion, 2, true, false});
  // The small-oscillation line only where it says something the exact one does not.
  if (small_oscillation_period > 0 && std::abs(small_oscillation_period - exact_period) > 1e-9 * small_oscillation_period)
    line(small_oscillation_period, "small-oscillation", reference_style());
  return figure;
}

}  // namespace vibra::scenes
