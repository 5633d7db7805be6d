// Picks and builds the scene a config asks for: a system's diagram with panels, or plots alone.
#include "scenes/scene_factory.hpp"

#include <algorithm>
#include <iterator>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/quoted_value.hpp"
#include "scenes/diagrams/comparison_diagram.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/figures/plot_scene.hpp"
#include "scenes/panels/plot_panels.hpp"
#include "scenes/system_scene.hpp"

namespace vibra::scenes {

namespace {
SceneStyle style_of(const SceneConfig& config, const TrajectoryInfo& info, const std::string& caption) {
  SceneStyle style;
  style.layout = config.layout;
  style.colors = config.colors;
  style.period = info.mesh.period;
  style.caption = caption;
  style.window = window_width(config, info.mesh.period);
  // A window narrower than a time step shows no curve, and its pixel columns
  // would be narrower than the resolution of t (--window 1e-300 corrupted the
  // heap): the range's lower end depends on dt, so it is checked here.
  if (style.window > 0 && style.window < info.mesh.dt)
    throw UsageError("window=" + quoted_value(config.window) + " is narrower than one time step, dt = " +
                     short_number(info.mesh.dt) + ": give a window of several steps, e.g. window=" +
                     short_number(100 * info.mesh.dt) + ", or lower dt");
  style.window_mode = style.window > 0 ? config.window_mode : WindowMode::whole_run;
  if (style.window > 0 && style.window >= info.mesh.T) style.window_mode = WindowMode::whole_run;
  style.title = config.title;
  if (config.equation) style.equation = model_equation(find_model(config.model), model_parameters_of(config));
  for (const std::string& note : config.notes) style.notes.push_back(parse_note(note));
  return style;
}

/// A member's main quantity, or its exact solution, read from a comparison's row.
SeriesSpec main_series(const MemberColumns& columns, double factor, render::Color color) {
  return {"", color, columns.reading([factor](std::span<const double> row) { return factor * row[1]; })};
}
SeriesSpec exact_series(const std::function<double(double)>& exact, double factor, render::Color color) {
  return {"", color.with_alpha(0.8), [exact, factor](std::span<const double> row) { return factor * exact(row[0]); },
          true, [exact, factor](double t) { return factor * exact(t); }};
}
/// The diagram an option that marks it (--annotate, --exaggerate) applies
/// to; refused in the layouts without a diagram.
const DiagramKind& marked_diagram(const SceneConfig& config, const std::string& option) {
  if (config.layout == Layout::plot || config.layout == Layout::grid)
    throw UsageError(option + " marks the diagram: use --layout fbd or fbd+plot, or drop " + option);
  return diagram_for(config);
}

void check_panel_options(const SceneConfig& config) {
  // A single run's plot layout stacks the chosen panels; a comparison's plot
  // is its main quantity, one curve per member.
  const bool stacked = config.layout == Layout::plot && config.compare.empty();
  if (!config.panels.empty() && config.layout != Layout::fbd_plot && !stacked)
    throw UsageError("panels are drawn beside the diagram: use --layout fbd+plot, or drop --panels");
  if (config.energy_bars && (config.layout == Layout::plot || config.layout == Layout::grid))
    throw UsageError("energy bars stand beside the diagram: use --layout fbd or fbd+plot, or drop --energy-bars");
  if (config.exaggerate > 1) {
    const DiagramKind& kind = marked_diagram(config, "--exaggerate");
    if (!kind.exaggerates)
      throw UsageError("--exaggerate draws small motions larger, and the " + kind.name +
                       " diagram is drawn true to scale: drop --exaggerate (the bumpy road has it)");
  }
  for (const auto& name : config.annotate) {
    const DiagramKind& kind = marked_diagram(config, "--annotate " + name);
    if (std::find(kind.annotations.begin(), kind.annotations.end(), name) != kind.annotations.end()) continue;
    std::string drawn_on;
    for (const DiagramKind& other : all_diagrams())
      if (std::find(other.annotations.begin(), other.annotations.end(), name) != other.annotations.end())
        drawn_on += (drawn_on.empty() ? "" : ", ") + other.name;
    throw UsageError("--annotate " + name + " is drawn on the " + drawn_on + " diagram, and this scene's is " +
                     kind.name + ": render a model it draws, or drop --annotate");
  }
}

/// A comparison's panel `name`: each member's curves (or phase curves) in its
/// colour, read from its columns; the references (exact solution, exact
/// period) once in ink when the members solve one problem, else each member's
/// in its colour.
QuantityPanelSpec comparison_panel(const std::string& name, const Comparison& comparison,
                                   const std::vector<MemberColumns>& columns, const std::vector<LegendEntry>& legend) {
  QuantityPanelSpec combined;
  for (size_t i = 0; i < columns.size(); ++i) {
    const bool shared = comparison.same_problem();
    QuantityPanelSpec member = quantity_panel(name, comparison.trajectory(i).info(), legend[i].color, "",
                                              shared ? render::palette::ink : legend[i].color);
    if (i == 0) {
      combined.label = member.label, combined.x_label = member.x_label;
      combined.least_span = member.least_span, combined.empty_note = member.empty_note;
      combined.equal_scales = member.equal_scales;
    }
    for (SeriesSpec& c : member.curves) c.value = columns[i].reading(std::move(c.value)), c.label.clear();
    for (SeriesSpec& r : member.references) r.value = columns[i].reading(std::move(r.value)), r.label.clear();
    for (PhaseCurveSpec& c : member.phase)
      c.x = columns[i].reading(std::move(c.x)), c.y = columns[i].reading(std::move(c.y)), c.label.clear();
    std::move(member.curves.begin(), member.curves.end(), std::back_inserter(combined.curves));
    std::move(member.phase.begin(), member.phase.end(), std::back_inserter(combined.phase));
    if (!shared || i == 0)
      std::move(member.references.begin(), member.references.end(), std::back_inserter(combined.references));
  }
  return combined;
}
}  // namespace

std::unique_ptr<Scene> make_scene(const SceneConfig& config, const TrajectoryInfo& info, const std::string& caption) {
  if (config.layout == Layout::grid)
    throw UsageError("layout grid draws a comparison's members in a panel each: add --compare KEY=V1,V2,... "
                     "or choose fbd, fbd+plot or plot");
  check_panel_options(config);
  const SceneStyle style = style_of(config, info, caption);
  if (config.layout == Layout::plot) {
    if (config.panels.empty())
      return std::make_unique<PlotScene>(config.width, config.height, info, style,
                                         std::vector{main_quantity_panel(style, info.columns[1], info.exact, info.exact_label)});
    // --panels without a diagram: the chosen panels against time, one above another.
    std::vector<PanelSpec> stacked;
    for (const auto& name : config.panels) {
      QuantityPanelSpec q = quantity_panel(name, info, config.colors.bob, "", render::palette::vermillion);
      if (q.is_phase())
        throw UsageError("panel '" + name + "' is the phase plane, which the plot layout does not draw: choose "
                         "panels against time here, or a model with a diagram and --layout fbd+plot");
      PanelSpec panel{std::move(q.label), std::move(q.curves), q.least_span, std::move(q.empty_note), name};
      for (auto& reference : q.references) panel.series.push_back(std::move(reference));
      stacked.push_back(std::move(panel));
    }
    return std::make_unique<PlotScene>(config.width, config.height, info, style, std::move(stacked));
  }
  const DiagramKind& kind = diagram_for(config);
  const Parameters parameters = model_parameters_of(config);
  std::vector<QuantityPanelSpec> panels;
  for (const auto& name : config.panels)
    panels.push_back(quantity_panel(name, info, config.colors.bob, "", render::palette::vermillion));
  std::unique_ptr<EnergyBars> bars = config.energy_bars ? std::make_unique<EnergyBars>(info) : nullptr;
  return std::make_unique<SystemScene>(config.width, config.height, info, style, kind.make({config, parameters, info}),
                                       std::move(panels), std::move(bars));
}

std::unique_ptr<Trajectory> build_scene_runs(const SceneConfig& config) {
  const ModelDefinition& model = find_model(config.model);
  if (config.compare.empty()) return model.build(model_parameters_of(config));
  const ComparisonRequest request = parse_comparison(config.compare);
  return std::make_unique<ComparisonTrajectory>(model, comparison_base_of(config, request.key), request);
}

std::unique_ptr<Scene> make_scene_for(const SceneConfig& config, const Trajectory& runs, const std::string& caption) {
  if (const auto* comparison = dynamic_cast<const ComparisonTrajectory*>(&runs))
    return make_comparison_scene(config, *comparison, caption);
  return make_scene(config, runs.info(), caption);
}

namespace {
/// A comparison's members as its scene draws them: their columns and legend entries.
struct ComparisonMembers {
  std::vector<MemberColumns> columns;
  std::vector<LegendEntry> legend;
};

ComparisonMembers comparison_members(const SceneConfig& config, const ComparisonTrajectory& runs) {
  const Comparison& comparison = runs.comparison();
  ComparisonMembers m;
  for (size_t i = 0; i < comparison.size(); ++i) {
    m.columns.push_back(MemberColumns::of(runs, i));
    m.legend.push_back({member_markup(comparison, i), member_color(config.colors.bob, i), false,
                        m.columns[i].reading([](std::span<const double> row) { return row[1]; }),
                        [ends = runs.early_ends(), i] { return (*ends)[i]; }});
    // --equation with a comparison of schemes: each scheme's update formula under its name.
    if (config.equation && comparison.request().key == "scheme")
      m.legend.back().formula = std::string(scheme_info(comparison.trajectory(i).info().mesh.scheme).formula);
  }
  return m;
}

/// Layout plot: every member's curve in one panel, with the exact solution(s).
std::unique_ptr<Scene> comparison_plot_scene(const SceneConfig& config, const ComparisonTrajectory& runs,
                                             const SceneStyle& style, ComparisonMembers m) {
  const Comparison& comparison = runs.comparison();
  const TrajectoryInfo& first = comparison.trajectory(0).info();
  const bool shared_exact = comparison.same_problem();
  const double factor = display_factor(first.columns[1]);
  PanelSpec panel{quantity_markup(first.columns[1]), {}};
  for (size_t i = 0; i < m.columns.size(); ++i) panel.series.push_back(main_series(m.columns[i], factor, m.legend[i].color));
  for (size_t i = 0; i < m.columns.size(); ++i) {
    const auto& exact = comparison.trajectory(i).info().exact;
    if (exact && (!shared_exact || i == 0))
      panel.series.push_back(exact_series(exact, factor, shared_exact ? render::palette::ink : m.legend[i].color));
  }
  if (first.exact)
    m.legend.push_back({first.exact_label + (shared_exact ? "" : " (dashed)"),
                        shared_exact ? render::palette::ink : render::palette::faint, true});
  return std::make_unique<PlotScene>(config.width, config.height, runs.info(), style, std::vector{std::move(panel)},
                                     std::move(m.legend));
}

/// Layout grid: each member in a panel of its own, named on its axis: no legend needed.
std::unique_ptr<Scene> comparison_grid_scene(const SceneConfig& config, const ComparisonTrajectory& runs,
                                             const SceneStyle& style, const ComparisonMembers& m) {
  const Comparison& comparison = runs.comparison();
  const TrajectoryInfo& first = comparison.trajectory(0).info();
  const double factor = display_factor(first.columns[1]);
  std::vector<PanelSpec> panels;
  for (size_t i = 0; i < m.columns.size(); ++i) {
    PanelSpec panel{quantity_markup(first.columns[1]) + "  " + m.legend[i].label,
                    {main_series(m.columns[i], factor, m.legend[i].color)}};
    if (const auto& exact = comparison.trajectory(i).info().exact)
      panel.series.push_back(exact_series(exact, factor, render::palette::ink));
    panels.push_back(std::move(panel));
  }
  return std::make_unique<PlotScene>(config.width, config.height, runs.info(), style, std::move(panels));
}

/// One member's scene settings for the comparison's diagram: its run's colour.
SceneConfig member_config(const SceneConfig& config, render::Color color) {
  SceneConfig member = config;
  member.colors.bob = color;
  // Here a hue names a run: the forces (drawn for the first run) are in
  // charcoal, not in the hues of runs, unless a scene file chose theirs.
  const SceneColors defaults;
  for (auto [force, by_default] : {std::pair{&member.colors.gravity, defaults.gravity},
                                   {&member.colors.wire_force, defaults.wire_force}, {&member.colors.drag, defaults.drag}})
    if (*force == by_default) *force = render::palette::charcoal;
  // Each member would choose its own factor from its own run: one scale for
  // all, the one given or true scale, keeps the ghosts comparable.
  if (member.exaggerate == 0) member.exaggerate = 1;
  return member;
}
}  // namespace

std::unique_ptr<Scene> make_comparison_scene(const SceneConfig& config, const ComparisonTrajectory& runs,
                                             const std::string& caption) {
  check_panel_options(config);
  const Comparison& comparison = runs.comparison();
  const SceneStyle style = style_of(config, runs.info(), caption);
  ComparisonMembers m = comparison_members(config, runs);
  if (config.layout == Layout::plot) return comparison_plot_scene(config, runs, style, std::move(m));
  if (config.layout == Layout::grid) return comparison_grid_scene(config, runs, style, m);
  if (config.energy_bars) throw UsageError("energy bars show one run's energy: drop --energy-bars, or --compare");
  std::vector<QuantityPanelSpec> panels;
  for (const auto& name : config.panels) panels.push_back(comparison_panel(name, comparison, m.columns, m.legend));
  const DiagramKind& kind = diagram_for(config);
  std::vector<ComparisonDiagram::Member> members;
  for (size_t i = 0; i < m.columns.size(); ++i)
    members.push_back({kind.make({member_config(config, m.legend[i].color), comparison.parameters(i),
                                  comparison.trajectory(i).info()}),
                       m.columns[i], std::move(m.legend[i])});
  return std::make_unique<SystemScene>(
      config.width, config.height, runs.info(), style,
      std::make_unique<ComparisonDiagram>(std::move(members), comparison.same_problem(),
                                          comparison.trajectory(0).info().exact_label),
      std::move(panels));
}

}  // namespace vibra::scenes
