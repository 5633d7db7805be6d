// The chapter's experiments (vibra.convergence, vibra.energy, ...): the same
// functions as `vibra analyze`, their tables handed over as named numpy
// columns, their figures written on request.
#include <optional>

#include "jobs/experiments/experiments.hpp"
#include "bindings.hpp"

namespace vibra::python {

namespace {
using Text = std::optional<std::string>;

/// One table column as a numpy array: float64, int64 or str.
py::object column_array(const app::Table& table, size_t column) {
  py::list cells;
  bool text = false;
  for (size_t row = 0; row < table.rows(); ++row) {
    std::visit(
        [&](const auto& value) {
          using T = std::decay_t<decltype(value)>;
          text |= std::is_same_v<T, std::string>;
          cells.append(value);
        },
        table.cell(row, column));
  }
  py::module_ numpy = py::module_::import("numpy");
  if (text) return numpy.attr("array")(cells, py::arg("dtype") = "str");
  const bool integers = table.rows() > 0 && std::holds_alternative<long long>(table.cell(0, column));
  return numpy.attr("array")(cells, py::arg("dtype") = integers ? "int64" : "float64");
}

/// [(heading, [(name, array), ...], conclusion), ...] after writing the
/// figure if asked; the result's conclusion goes with its last table.
template <class Options>
py::list run(app::ExperimentResult (*experiment)(const Options&), const Options& options, const std::string& figure,
             const std::string& size) {
  app::check_figure_output(figure, size);
  app::ExperimentResult result;
  {
    py::gil_scoped_release release;
    result = experiment(options);
    app::write_figure(result, figure, size);
  }
  py::list tables;
  for (size_t t = 0; t < result.tables.size(); ++t) {
    const app::TitledTable& titled = result.tables[t];
    py::list columns;
    for (size_t c = 0; c < titled.table.columns().size(); ++c)
      columns.append(py::make_tuple(titled.table.columns()[c], column_array(titled.table, c)));
    tables.append(py::make_tuple(titled.heading, columns, t + 1 == result.tables.size() ? result.conclusion : ""));
  }
  return tables;
}

void set(std::string& field, const Text& value) {
  if (value) field = *value;
}
}  // namespace

void bind_analyses(py::module_& m) {
  m.def(
      "convergence",
      [](const std::string& model, const std::vector<std::string>& settings, std::optional<int> levels,
         const std::string& figure,
         const std::string& size) {
        return run(&app::convergence_experiment, app::ConvergenceOptions{model, settings, levels, ""}, figure, size);
      },
      py::arg("model"), py::arg("settings"), py::arg("levels"), py::arg("figure"), py::arg("size"));
  m.def(
      "energy",
      [](const Text& schemes, const Text& T, const Text& dt, const std::string& figure, const std::string& size) {
        app::EnergyOptions o;
        set(o.schemes, schemes), set(o.T, T), set(o.dt, dt);
        return run(&app::energy_experiment, o, figure, size);
      },
      py::arg("schemes"), py::arg("T"), py::arg("dt"), py::arg("figure"), py::arg("size"));
  m.def(
      "empirical",
      [](const std::string& model, const std::vector<std::string>& settings, const Text& dt, bool mesh_extrema,
         const std::string& figure, const std::string& size) {
        return run(&app::empirical_experiment, app::EmpiricalOptions{model, settings, dt.value_or(""), mesh_extrema},
                   figure, size);
      },
      py::arg("model"), py::arg("settings"), py::arg("dt"), py::arg("mesh_extrema"), py::arg("figure"),
      py::arg("size"));
  m.def(
      "frequency",
      [](const Text& w, const Text& steps_per_period, const std::string& figure, const std::string& size) {
        app::FrequencyOptions o;
        set(o.w, w), set(o.steps_per_period, steps_per_period);
        return run(&app::frequency_experiment, o, figure, size);
      },
      py::arg("w"), py::arg("steps_per_period"), py::arg("figure"), py::arg("size"));
  m.def(
      "amplitude",
      [](const Text& schemes, const Text& dt, const Text& periods, const std::string& figure, const std::string& size) {
        app::AmplitudeOptions o;
        set(o.schemes, schemes), set(o.dt, dt), set(o.periods, periods);
        return run(&app::amplitude_experiment, o, figure, size);
      },
      py::arg("schemes"), py::arg("dt"), py::arg("periods"), py::arg("figure"), py::arg("size"));
  m.def(
      "orbit",
      [](const Text& scheme, const Text& steps_per_orbit, std::optional<long long> orbits, bool long_run,
         const std::string& figure, const std::string& size) {
        app::OrbitOptions o;
        set(o.scheme, scheme), set(o.steps_per_orbit, steps_per_orbit);
        if (orbits) o.orbits = *orbits;
        o.long_run = long_run;
        return run(&app::orbit_experiment, o, figure, size);
      },
      py::arg("scheme"), py::arg("steps_per_orbit"), py::arg("orbits"), py::arg("long_run"), py::arg("figure"),
      py::arg("size"));
}

}  // namespace vibra::python
