// The figure vibra plot --compare draws without --panels: paths or curves against t and the phase plane.
#include "scenes/figures/comparison_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "render/output/stop_signal.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/figures/friction_panel.hpp"
#include "scenes/panels/plot_panels.hpp"
#include "scenes/panels/rows_inside_step.hpp"
#include "scenes/overlays/run_caption.hpp"

namespace vibra::scenes {

namespace {
const render::SeriesStyle kExactStyle{render::palette::ink.with_alpha(0.75), 1.8, true, false};

/// A member's series in one panel, fed from two columns of its rows.
struct Feed {
  size_t member;
  int panel;
  render::Series* series;
  int x_column, y_column;
  double x_factor = 1, y_factor = 1;  ///< display_factor of each column
};

/// The exact solution over [0, T]: finer than the mesh (its envelope keeps every peak) and 4 samples per pixel column.
void add_exact_curve(render::Series& series, const TrajectoryInfo& info, double T, long long steps, int width) {
  const long long samples = std::max(4LL * width, steps);
  const double f = display_factor(info.columns[1]);
  for (long long i = 0; i <= samples; ++i) series.add(T * i / samples, f * info.exact(T * i / samples));
}

/// The exact solution in the phase plane, its velocity by a centered
/// difference (error ~1e-10, far below a pixel), over one period or [0, T].
void add_exact_phase(render::Series& series, const TrajectoryInfo& info, double T) {
  const double period = info.exact_period > 0 ? info.exact_period : info.mesh.period;
  const double span = period > 0 ? std::min(T, period) : T, h = 1e-5 * span;
  const double velocity_factor = phase_velocity_axis(info).factor;
  for (int i = 0; i <= 2000; ++i) {
    const double t = span * i / 2000;
    series.add(display_factor(info.columns[1]) * info.exact(t),
               velocity_factor * (info.exact(t + h) - info.exact(t - h)) / (2 * h));
  }
}
}  // namespace

std::vector<std::string> default_comparison_panels(const TrajectoryInfo& info) {
  if (column_index(info, "x") > 0 && column_index(info, "y") > 0) return {"path"};
  return {info.columns[1], "phase"};
}

namespace {
/// The figure being built, and what its panels are fed from.
struct ComparisonPlot {
  render::Figure& figure;
  Comparison& comparison;
  double T;
  long long steps;  ///< the finest member's
  int width;
  /// Comparing schemes or time steps: one problem, one exact solution.
  /// Comparing a model key: each member has its own, dashed in its colour.
  bool shared_exact;
  std::vector<Feed> feeds;
  std::vector<std::vector<render::Series*>> labelled;  ///< the legend's entries, per member
  std::optional<FrictionPanel> friction;
};

/// The exact solutions in panel `p`: one shared, or each member's dashed in its colour.
void add_exact_curves(ComparisonPlot& plot, int p, bool time_panel, bool legend) {
  for (size_t m = 0; m < plot.comparison.size(); ++m) {
    const TrajectoryInfo& info = plot.comparison.trajectory(m).info();
    if (!info.exact || (plot.shared_exact && m > 0)) continue;
    render::SeriesStyle style = kExactStyle;
    if (!plot.shared_exact) style.color = render::palette::series(m).with_alpha(0.8), style.line_width = 1.4;
    const std::string label = legend && (plot.shared_exact || m == 0) ? info.exact_label + " (dashed)" : "";
    const std::string own = plot.shared_exact ? label : "";
    render::Series& exact = time_panel ? plot.figure.add_curve(p, own, style, 0, plot.T) : plot.figure.add_path(p, own, style);
    if (!plot.shared_exact && !label.empty()) plot.figure.add_points(p, label, kExactStyle);  // a legend entry only
    if (time_panel) add_exact_curve(exact, info, plot.T, plot.steps, plot.width);
    else add_exact_phase(exact, info, plot.T);
  }
}

/// A panel of `name` (a column against t, the path or the phase plane) with
/// a curve per member, and the exact solution where it is the main quantity.
void add_member_panel(ComparisonPlot& plot, const std::string& name) {
  const TrajectoryInfo& first = plot.comparison.trajectory(0).info();
  const bool time_panel = name != "path" && name != "phase";
  const int x = name == "path" ? column_index(first, "x") : time_panel ? 0 : 1;
  const PhaseVelocityAxis phase = phase_velocity_axis(first);
  const int y = name == "path" ? column_index(first, "y") : name == "phase" ? phase.column : column_index(first, name);
  render::PanelOptions options{name == "phase" ? phase.label : quantity_markup(first.columns[y]),
                               quantity_markup(first.columns[x]), render::AxisScale::linear, render::AxisScale::linear,
                               name == "path" || (name == "phase" && phase.equal_scales)};
  if (time_panel) options.x_range = std::make_pair(0.0, plot.T);
  const int p = plot.figure.add_panel(options);
  const bool legend = p == 0;  // the colours are the same in every panel
  for (size_t m = 0; m < plot.comparison.size(); ++m) {
    const render::SeriesStyle style{render::palette::series(m), 2.2};
    const std::string label = legend ? member_markup(plot.comparison, m) : "";
    render::Series& s = time_panel ? plot.figure.add_curve(p, label, style, 0, plot.T) : plot.figure.add_path(p, label, style);
    // Each member's own w: comparing a model key, their periods differ.
    const double fy = name == "phase" ? phase_velocity_axis(plot.comparison.trajectory(m).info()).factor
                                      : display_factor(first.columns[y]);
    plot.feeds.push_back({m, p, &s, x, y, display_factor(first.columns[x]), fy});
    if (legend) plot.labelled[m].push_back(&s);
  }
  if (name == first.columns[1] || name == "phase") add_exact_curves(plot, p, time_panel, legend);
}

/// Every member's rows, and rows inside its steps, into its series; returns each member's last row.
std::vector<std::vector<double>> feed_runs(ComparisonPlot& plot) {
  std::vector<std::vector<double>> last(plot.comparison.size());
  std::vector<double> between;
  long long samples = 0;
  plot.comparison.advance_to(plot.T, [&](size_t member, std::span<const double> row) {
    auto feed = [&](std::span<const double> r) {
      for (const Feed& f : plot.feeds)
        if (f.member == member) f.series->add(f.x_factor * r[f.x_column], f.y_factor * r[f.y_column]);
      if (plot.friction) plot.friction->observe(member, r);
    };
    const Trajectory& run = plot.comparison.trajectory(member);
    between.resize(row.size());
    if (!last[member].empty())
      rows_inside_step(run, last[member][0], inside_step_spacing(run.info().mesh, plot.width), between, feed);
    feed(row);
    last[member].assign(row.begin(), row.end());
    poll_stop(++samples);
  });
  return last;
}

/// Where a member left the view or blew up: a dot at its last point and a note in the legend.
void mark_early_ends(ComparisonPlot& plot, const std::vector<std::vector<double>>& last) {
  for (size_t m = 0; m < plot.comparison.size(); ++m) {
    if (!plot.comparison.blew_up(m)) continue;
    for (render::Series* s : plot.labelled[m])
      s->set_label(s->label() + ": " + early_end_note(plot.comparison.early_end(m), plot.comparison.blow_up_time(m)));
    for (const Feed& f : plot.feeds)
      if (f.member == m && !last[m].empty())
        plot.figure.add_points(f.panel, "", {render::palette::series(m), 0, false, true})
            .add(f.x_factor * last[m][f.x_column], f.y_factor * last[m][f.y_column]);
  }
}
}  // namespace

render::Figure comparison_figure(Comparison& comparison, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title) {
  const TrajectoryInfo& first = comparison.trajectory(0).info();
  const double T = comparison.end_time();
  if (!std::isfinite(T)) throw UsageError("a plot needs a finite end time: give T or periods");
  long long steps = 0;
  for (size_t m = 0; m < comparison.size(); ++m) steps = std::max(steps, comparison.trajectory(m).info().mesh.steps);
  comparison.set_view_limits();
  render::Figure figure(width, height, title);
  ComparisonPlot plot{figure, comparison, T, steps, width, comparison.same_problem(), {}, {}, {}};
  plot.labelled.resize(comparison.size());
  for (const auto& name : panel_order(first, panels)) {
    if (name != "friction") {
      add_member_panel(plot, name);
      continue;
    }
    std::vector<FrictionPanel::Member> members;
    for (size_t m = 0; m < comparison.size(); ++m)
      members.push_back({&comparison.trajectory(m).info(), render::palette::series(m), member_markup(comparison, m)});
    plot.friction.emplace(figure, std::move(members));
  }
  const std::vector<std::vector<double>> last = feed_runs(plot);
  if (plot.friction) plot.friction->finish();
  mark_early_ends(plot, last);
  return figure;
}

}  // namespace vibra::scenes
