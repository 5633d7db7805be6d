#include <cmath>
#include <cstdio>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "cli/model_help.hpp"
#include "core/analysis/empirical.hpp"
#include "core/analysis/parameters_with_dt.hpp"
#include "core/error.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::cli {

namespace {
struct EmpiricalOptions {
  std::string model;
  std::vector<std::string> settings;
  std::string dt;
  bool mesh_extrema = false;
  AnalysisOutput output;
};

void run(const EmpiricalOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze empirical needs a MODEL, e.g. vibra analyze empirical undamped --dt 0.1,0.05");
  check_output(o.output);
  const ModelDefinition& model = find_model(o.model);
  // Without --dt, the one run the settings describe.
  std::vector<Parameters> runs;
  if (o.dt.empty())
    runs.push_back(model_settings(o.model, o.settings));
  else
    for (double dt : positive_list("--dt", o.dt)) runs.push_back(parameters_with_dt(model, o.settings, dt));

  const ExtremumTiming timing = o.mesh_extrema ? ExtremumTiming::mesh : ExtremumTiming::fitted;
  Table table({"dt", "i", "t", "period", "angular_frequency", "amplitude"});
  std::vector<scenes::LabelledCycles> labelled;
  TrajectoryInfo info;
  for (const Parameters& p : runs) {
    auto trajectory = model.build(p);
    info = trajectory->info();
    const double dt = info.mesh.dt;
    auto cycles = oscillation_cycles(*trajectory, timing);
    if (cycles.empty()) {
      char message[200];
      std::snprintf(message, sizeof message,
                    "no complete oscillation (two maxima and a minimum) of %s with dt=%g: raise T or periods",
                    info.columns[1].c_str(), dt);
      throw UsageError(message);
    }
    for (const auto& c : cycles) table.add_row({dt, static_cast<long long>(c.i), c.t, c.period, 2 * M_PI / c.period, c.amplitude});
    char label[64];
    std::snprintf(label, sizeof label, "Δ<i>t</i> = %g", dt);
    labelled.push_back({label, std::move(cycles)});
  }
  const std::string quantity = info.columns[1];
  print_table(o.output,
              "Empirical periods and amplitudes of " + quantity + " (" + o.model + ", " +
                  std::string(scheme_info(info.mesh.scheme).name) + "), extrema " +
                  (o.mesh_extrema ? "at mesh points" : "placed by a sinusoid through three samples"),
              table);
  const double reference_w = info.mesh.period > 0 ? 2 * M_PI / info.mesh.period : 0;
  char reference[96];
  std::snprintf(reference, sizeof reference, "%s <i>ω</i> = %.4g", info.exact_label == "exact" ? "exact" : "small-oscillation",
                reference_w);
  write_figure(o.output, [&](int w, int h) {
    return scenes::empirical_figure(labelled, reference_w, reference,
                                    "Empirical frequency and amplitude of " + o.model + ", " +
                                        std::string(scheme_info(info.mesh.scheme).name),
                                    w, h);
  });
}
}  // namespace

void add_empirical_analysis(CLI::App& analyze) {
  auto o = std::make_shared<EmpiricalOptions>();
  CLI::App* cmd = analyze.add_subcommand("empirical", "Local periods and amplitudes from the extrema of the main quantity");
  cmd->add_option("MODEL", o->model, "Model name (vibra solve --help lists them)");
  cmd->add_option("--set", o->settings, "KEY=VALUE model setting, repeatable")->allow_extra_args(false);
  cmd->add_option("--dt", o->dt, "Comma-separated time steps, one run each (default: the model's dt)");
  cmd->add_flag("--mesh-extrema", o->mesh_extrema,
                "Place extrema at mesh points as the book's code does (periods become multiples of dt)");
  add_output_options(*cmd, o->output);
  cmd->footer("Example (the book's Figure 1.3):\n"
              "  vibra analyze empirical undamped --dt 0.1,0.05,0.025 --set periods=20 -o empirical.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
