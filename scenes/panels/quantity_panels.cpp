// The panels `vibra render --panels` can put beside a diagram: any of the model's columns against t, and `phase`, `energy`, `error`, `period`.
#include "scenes/panels/quantity_panels.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "scenes/panels/period_track.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

namespace {
/// A column's symbol alone, for formulas such as u − u_e.
std::string symbol_markup(const std::string& column) {
  if (column == "theta") return "<i>θ</i>";
  if (column == "omega") return "<i>ω</i>";
  return quantity_markup(column);
}

SeriesSpec column_curve(int column, double factor, render::Color color, const std::string& label) {
  return {label, color, [column, factor](std::span<const double> r) { return factor * r[column]; }};
}

/// (E - E(0))/|E(0)| with E(0) from the first row fed, as `vibra solve
/// --energy` computes its E_rel column.
SeriesSpec energy_curve(const TrajectoryInfo& info, render::Color color, const std::string& label) {
  auto E0 = std::make_shared<double>(NAN);
  return {label, color, [E0, energy = info.energy](std::span<const double> r) {
            const double E = energy(r).total();
            if (std::isnan(*E0)) *E0 = E;
            return relative_energy_change(E, *E0);
          }};
}

SeriesSpec period_curve(const TrajectoryInfo& info, render::Color color, const std::string& label) {
  auto track = std::make_shared<PeriodTrack>(1, velocity_column(info));
  SeriesSpec curve{label, color, [track](std::span<const double> r) { return track->at(r); }};
  curve.mesh_values = false;  // a running measure, held between the crossings it is measured at
  return curve;
}

/// The period the measured ones are held against, named by its formula: the
/// exact one where known (2π/ω, the pendulum's 4K(sin Θ/2)), else the
/// small-oscillation period.
std::optional<SeriesSpec> period_reference(const TrajectoryInfo& info, render::Color color) {
  const bool exact = info.exact_period > 0;
  const double P = exact ? info.exact_period : info.mesh.period;
  if (!(P > 0)) return std::nullopt;
  const std::string name = exact ? (info.exact_period_label.empty() ? "exact period" : info.exact_period_label)
                                 : info.small_period_label;
  SeriesSpec line{name, color, [P](std::span<const double>) { return P; }, true};
  line.mesh_values = false;
  return line;
}
}  // namespace

std::vector<std::string> render_panel_names(const TrajectoryInfo& info) {
  std::vector<std::string> names(info.columns.begin() + 1, info.columns.end());
  names.insert(names.end(), {"phase", "energy", "error", "period"});
  return names;
}

QuantityPanelSpec quantity_panel(const std::string& name, const TrajectoryInfo& info, render::Color color,
                                 const std::string& curve_label, render::Color reference_color) {
  const std::vector<std::string> valid = render_panel_names(info);
  if (std::find(valid.begin(), valid.end(), name) == valid.end()) reject_unknown_panel(name, valid);
  const std::string& main = info.columns[1];
  const std::string u = symbol_markup(main);
  const double f = display_factor(main);
  QuantityPanelSpec spec;
  if (name == "phase") {
    const PhaseVelocityAxis axis = phase_velocity_axis(info);
    spec.x_label = quantity_markup(main);
    spec.label = axis.label;
    spec.equal_scales = axis.equal_scales;
    spec.phase.push_back({curve_label, color, [f](std::span<const double> r) { return f * r[1]; },
                          [v = axis.column, fv = axis.factor](std::span<const double> r) { return fv * r[v]; }});
  } else if (name == "energy") {
    if (!info.energy)
      throw UsageError("this model has no mechanical energy to plot: drop 'energy' from --panels");
    spec.label = "(<i>E</i> − <i>E</i><sub>0</sub>) / |<i>E</i><sub>0</sub>|  energy change";
    spec.curves.push_back(energy_curve(info, color, curve_label));
    spec.empty_note = "E(0) = 0: no relative change";
  } else if (name == "error") {
    if (!info.exact)
      throw UsageError(std::string("this run has no exact solution to take the error from: drop 'error' from --panels (") +
                       kRunsWithExactSolution + ")");
    spec.label = u + " − " + u + "<sub>" + info.exact_label + "</sub>  error";
    spec.curves.push_back(
        {curve_label, color, [exact = info.exact, f](std::span<const double> r) { return f * (r[1] - exact(r[0])); }});
  } else if (name == "period") {
    spec.label = "period of " + u + ", measured";
    spec.curves.push_back(period_curve(info, color, curve_label.empty() ? "measured" : curve_label));
    spec.empty_note = u + " crosses zero upward fewer than twice in this run: no period measured";
    if (auto reference = period_reference(info, reference_color)) {
      // At least ±1% of the period: an accurate scheme's periods sit on the line.
      spec.least_span = 0.02 * reference->value({});
      spec.references.push_back(std::move(*reference));
    }
  } else {
    const int column = column_index(info, name);
    spec.label = quantity_markup(name);
    const bool with_exact = column == 1 && info.exact;
    const double fc = display_factor(name);
    spec.curves.push_back(column_curve(column, fc, color, curve_label.empty() && with_exact ? "numerical" : curve_label));
    if (with_exact)
      spec.references.push_back({info.exact_label, reference_color,
                                 [exact = info.exact, fc](std::span<const double> r) { return fc * exact(r[0]); }, true,
                                 [exact = info.exact, fc](double t) { return fc * exact(t); }});
  }
  return spec;
}

std::unique_ptr<ScenePanel> make_scene_panel(QuantityPanelSpec spec, const TrajectoryInfo& info,
                                             const render::PixelRect& outer, double scale, WindowMode mode, double window) {
  if (spec.is_phase()) {
    const double trail = info.mesh.period > 0 ? std::min(info.mesh.period, info.mesh.T) : info.mesh.T / 8;
    auto panel = std::make_unique<PhasePanel>(outer, scale, std::move(spec.x_label), std::move(spec.label),
                                              std::move(spec.phase), trail);
    if (spec.equal_scales) panel->keep_equal_scales();
    return panel;
  }
  std::vector<SeriesSpec> series = std::move(spec.curves);
  for (auto& r : spec.references) series.push_back(std::move(r));
  auto panel = std::make_unique<SeriesPanel>(outer, scale, std::move(spec.label), std::move(series), info.mesh.T, mode, window);
  panel->mark_mesh_points(fixed_mesh_step(info));
  panel->set_least_span(spec.least_span);
  panel->set_empty_note(std::move(spec.empty_note));
  return panel;
}

}  // namespace vibra::scenes
